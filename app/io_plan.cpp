#include "app/io_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

#include "core/util/error.hpp"

namespace ts::app {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

[[noreturn]] void fail(const std::string& path, const std::string& problem, const std::string& what) {
    throw input_error(path, problem + " (" + what + ")");
}

std::string joined(const std::vector<std::string>& items) {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i) s += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
    return s;
}

// A directory we can create files in: exists, is a directory, and write + search access.
void check_writable_directory(const fs::path& dir, const std::string& path, const std::string& what) {
    std::error_code ec;
    const std::string shown = dir.string();
    if (!fs::exists(dir, ec)) fail(path, "output directory " + shown + " does not exist", what);
    if (!fs::is_directory(dir, ec)) fail(path, shown + " is not a directory", what);
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        fail(path, "cannot write in " + shown + ": " + std::strerror(errno), what);
}

fs::path parent_or_dot(const fs::path& p) { return p.parent_path().empty() ? fs::path(".") : p.parent_path(); }

void check_input(const std::string& what, const std::string& path) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st)) fail(path, "no such file", what);
    if (fs::is_directory(st)) fail(path, "is a directory, expected a file", what);
    if (::access(path.c_str(), R_OK) != 0) fail(path, std::string("cannot read: ") + std::strerror(errno), what);
}

void check_output(const std::string& what, const std::string& path, const std::vector<std::string>& extensions) {
    const fs::path p = path;
    std::error_code ec;
    if (fs::is_directory(p, ec)) fail(path, "is a directory, expected an output file name", what);
    const std::string ext = lower(p.extension().string());
    if (!extensions.empty() && std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
        fail(path, "unsupported output format '" + ext + "' (use " + joined(extensions) + ")", what);
    check_writable_directory(parent_or_dot(p), path, what);
}

void check_output_directory(const std::string& what, const std::string& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec).lexically_normal();
    if (!p.has_filename()) p = p.parent_path();  // "out/" names "out"
    if (fs::exists(p, ec)) {
        check_writable_directory(p, path, what);
        return;
    }
    // Created by the command with its missing parents: the nearest existing ancestor must take them.
    fs::path ancestor = p.parent_path();
    while (!fs::exists(ancestor, ec) && ancestor.has_relative_path()) ancestor = ancestor.parent_path();
    if (!fs::is_directory(ancestor, ec)) fail(path, ancestor.string() + " is not a directory", what);
    if (::access(ancestor.c_str(), W_OK | X_OK) != 0)
        fail(path, "cannot create it in " + ancestor.string() + ": " + std::strerror(errno), what);
}

// A file or folder as the file system knows it: the same (device, inode) is the same file
// whatever path names it (a symlink, "..", a hard link).
struct FileId {
    dev_t dev = 0;
    ino_t ino = 0;
    bool operator==(const FileId&) const = default;
};

std::optional<FileId> file_id(const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return std::nullopt;
    return FileId{st.st_dev, st.st_ino};
}

// Two outputs are the same file when their absolute, normalised paths agree (or, once they
// exist, their inodes).
bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec), cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    if (ca == cb) return true;
    const std::optional<FileId> ia = file_id(a), ib = file_id(b);
    return ia && ib && *ia == *ib;
}

// `p` and the folders holding it, innermost first, after symlinks and "..". A path that does not
// exist yet is represented by its nearest existing folder.
std::vector<FileId> self_and_folders(const fs::path& p) {
    std::error_code ec;
    fs::path at = fs::absolute(p, ec).lexically_normal();
    while (!fs::exists(at, ec) && at.has_relative_path()) at = at.parent_path();
    fs::path c = fs::canonical(at, ec);
    if (ec) c = at;
    std::vector<FileId> ids;
    for (;;) {
        if (const auto id = file_id(c)) ids.push_back(*id);
        if (!c.has_relative_path()) break;
        c = c.parent_path();
    }
    return ids;
}

bool contains(const std::vector<FileId>& ids, const FileId& id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Refuses an output that is an input, a folder an output is written into (or cleared) that holds
// an input, and an output inside a folder read as an input: a user's data is never written over.
void check_not_over_input(const std::string& out_what, const std::string& out, bool out_is_folder,
                          const std::string& in_what, const std::string& in, bool in_is_folder) {
    const std::optional<FileId> in_id = file_id(in);
    if (!in_id) return;  // check_input reported it
    const std::vector<FileId> out_chain = self_and_folders(out);
    const std::optional<FileId> out_id = file_id(out);
    const bool same = out_id && *out_id == *in_id;
    if (same)
        fail(out, "is the input " + in + ", which would be overwritten; write elsewhere", out_what + " and " + in_what);
    if (out_is_folder && out_id && contains(self_and_folders(in), *out_id))
        fail(out, "holds the input " + in + ", which writing or clearing it could overwrite; write elsewhere",
             out_what + " and " + in_what);
    if (in_is_folder && contains(out_chain, *in_id))
        fail(out, "is inside the input " + in + ", which would be changed; write elsewhere", out_what + " and " + in_what);
}

}  // namespace

IoPlan& IoPlan::input(std::string what, std::string path) {
    if (!path.empty()) inputs_.push_back({std::move(what), std::move(path), {}});
    return *this;
}

IoPlan& IoPlan::inputs(const std::string& what, const std::vector<std::string>& paths) {
    for (const auto& p : paths) input(what, p);
    return *this;
}

IoPlan& IoPlan::input_directory(std::string what, std::string path) {
    if (!path.empty()) input_directories_.push_back({std::move(what), std::move(path), {}});
    return *this;
}

IoPlan& IoPlan::output(std::string what, std::string path, std::vector<std::string> extensions) {
    if (!path.empty()) outputs_.push_back({std::move(what), std::move(path), std::move(extensions)});
    return *this;
}

IoPlan& IoPlan::output_directory(std::string what, std::string path) {
    if (!path.empty()) directories_.push_back({std::move(what), std::move(path), {}});
    return *this;
}

void IoPlan::check() {
    for (const Entry& e : inputs_) check_input(e.what, e.path);
    for (const Entry& e : input_directories_) {
        std::error_code ec;
        if (!fs::is_directory(e.path, ec)) fail(e.path, "no such folder", e.what);
    }
    // No output over an input, before anything else is said about the outputs.
    for (const auto* outs : {&outputs_, &directories_})
        for (const Entry& o : *outs) {
            for (const Entry& i : inputs_) check_not_over_input(o.what, o.path, outs == &directories_, i.what, i.path, false);
            for (const Entry& i : input_directories_)
                check_not_over_input(o.what, o.path, outs == &directories_, i.what, i.path, true);
        }
    for (const Entry& e : directories_) check_output_directory(e.what, e.path);
    for (std::size_t i = 0; i < outputs_.size(); ++i) {
        check_output(outputs_[i].what, outputs_[i].path, outputs_[i].extensions);
        for (std::size_t k = 0; k < i; ++k)
            if (same_file(outputs_[i].path, outputs_[k].path))
                fail(outputs_[i].path, "written twice", outputs_[k].what + " and " + outputs_[i].what);
    }
    for (const auto* outs : {&directories_, &outputs_})
        for (const Entry& o : *outs) locks_.push_back(std::make_unique<OutputLock>(o.path, o.what));
}

}  // namespace ts::app
