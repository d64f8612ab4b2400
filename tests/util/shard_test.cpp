#include "core/util/shard.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/util/error.hpp"

namespace {

ts::EnvironmentReader env(std::map<std::string, std::string> vars) {
    return [vars = std::move(vars)](const char* name) -> const char* {
        const auto it = vars.find(name);
        return it == vars.end() ? nullptr : it->second.c_str();
    };
}

TEST(Shard, ParsesKOfN) {
    const ts::Shard s = ts::parse_shard("3/8");
    EXPECT_EQ(s.index, 3);
    EXPECT_EQ(s.count, 8);
    EXPECT_EQ(ts::shard_text(s), "3/8");
}

TEST(Shard, RefusesMalformed) {
    for (const char* bad : {"", "3", "3/", "/8", "8/8", "-1/4", "1/0", "a/b", "1/2/3", "1.5/4", " 1/4", "1/4 "})
        EXPECT_THROW(ts::parse_shard(bad), ts::InputError) << bad;
}

TEST(Shard, SlurmArrayFromZero) {
    const auto s = ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "5"},
                                                   {"SLURM_ARRAY_TASK_MIN", "0"}}));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->index, 2);
    EXPECT_EQ(s->count, 5);
}

TEST(Shard, SlurmArrayNotFromZeroAndWithStep) {
    // --array=1-8: task 1 is shard 0.
    auto s = ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "8"},
                                             {"SLURM_ARRAY_TASK_MIN", "1"}}));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->index, 0);
    // --array=10-30:10 -> tasks 10, 20, 30 are shards 0, 1, 2 of 3.
    s = ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "30"}, {"SLURM_ARRAY_TASK_COUNT", "3"},
                                        {"SLURM_ARRAY_TASK_MIN", "10"}, {"SLURM_ARRAY_TASK_STEP", "10"}}));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->index, 2);
    EXPECT_EQ(s->count, 3);
}

TEST(Shard, KubernetesIndexedJob) {
    const auto s = ts::shard_from_environment(env({{"JOB_COMPLETION_INDEX", "4"}, {"TERRASHADE_SHARD_COUNT", "6"}}));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->index, 4);
    EXPECT_EQ(s->count, 6);
    EXPECT_THROW(ts::shard_from_environment(env({{"JOB_COMPLETION_INDEX", "4"}})), ts::InputError);
    EXPECT_THROW(ts::shard_from_environment(env({{"JOB_COMPLETION_INDEX", "6"}, {"TERRASHADE_SHARD_COUNT", "6"}})),
                 ts::InputError);
}

TEST(Shard, InconsistentEnvironmentIsAnError) {
    EXPECT_THROW(ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "2"}})), ts::InputError);
    EXPECT_THROW(ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "3"}})),
                 ts::InputError);
    EXPECT_THROW(ts::shard_from_environment(env({{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_COUNT", "3"},
                                                 {"SLURM_ARRAY_TASK_MIN", "0"}})),
                 ts::InputError);
    EXPECT_FALSE(ts::shard_from_environment(env({})));
}

TEST(Shard, FlagWinsOverEnvironment) {
    const auto e = env({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "5"}});
    EXPECT_EQ(ts::resolve_shard("0/1", e), (ts::Shard{0, 1}));
    EXPECT_EQ(ts::resolve_shard("", e), (ts::Shard{2, 5}));
    EXPECT_EQ(ts::resolve_shard("", env({})), (ts::Shard{0, 1}));
}

TEST(Shard, FrameRangesCoverEveryIndexOnce) {
    for (std::size_t frames : {0u, 1u, 2u, 7u, 100u, 101u})
        for (int n : {1, 2, 3, 7, 8, 150}) {
            std::size_t next = 0, smallest = frames, largest = 0;
            for (int k = 0; k < n; ++k) {
                const ts::IndexRange r = ts::frame_range(frames, {k, n});
                EXPECT_EQ(r.begin, next) << frames << " frames, shard " << k << "/" << n;
                EXPECT_LE(r.begin, r.end);
                next = r.end;
                smallest = std::min(smallest, r.size()), largest = std::max(largest, r.size());
            }
            EXPECT_EQ(next, frames);
            EXPECT_LE(largest - std::min(smallest, largest), 1u);
        }
}

}  // namespace

namespace {

TEST(ShardSet, CompleteSetPasses) {
    EXPECT_NO_THROW(ts::check_complete_shard_set({"b", "a", "c"}, {ts::Shard{1, 3}, ts::Shard{0, 3}, ts::Shard{2, 3}}));
}

TEST(ShardSet, ReportsMissingDuplicateAndForeign) {
    auto message = [](const std::vector<std::string>& names, const std::vector<std::optional<ts::Shard>>& shards) {
        try {
            ts::check_complete_shard_set(names, shards);
        } catch (const ts::InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"a", "c"}, {ts::Shard{0, 3}, ts::Shard{2, 3}}).find("1 of 3 shards missing (1)"), std::string::npos);
    EXPECT_NE(message({"a", "b"}, {ts::Shard{0, 2}, ts::Shard{0, 2}}).find("again"), std::string::npos);
    EXPECT_NE(message({"a", "b"}, {ts::Shard{0, 2}, ts::Shard{1, 3}}).find("the others are of 2"), std::string::npos);
    EXPECT_NE(message({"a", "b"}, {ts::Shard{0, 2}, std::nullopt}).find("not a finished shard"), std::string::npos);
}

}  // namespace
