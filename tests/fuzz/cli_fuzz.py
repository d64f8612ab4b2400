#!/usr/bin/env python3
"""A command-line fuzzer for terrashade: random and mutated argument lists for every command.

Each command's options come from its own --help (names, types, choices, required ones), so a
new option is fuzzed without touching this file. An argument list is made of valid-looking
values (small inputs, small sizes, so real work takes seconds) and mutations: wrong types,
huge/negative/NaN/inf numbers, empty strings, directories and binary files where files are
read, an input given as the output, duplicated and unknown flags, dropped required ones.

Every invocation runs in a fresh empty working directory, with the inputs in a read-only folder
beside it, HOME/XDG_CACHE_HOME/TMPDIR pointing at private folders, and a per-invocation timeout.
It must:
  - exit 0, 2 (an input error), 130 or 143 (interrupted); never 1 ("internal error"), another
    code, a signal, or the timeout;
  - leave every input byte for byte as it was, and nothing new in the inputs' folder;
  - create files only under the outputs named on its command line (in the working directory),
    the sphere cache, and nothing in TMPDIR or /tmp (an entry naming its pid) once it has ended.

Usage: cli_fuzz.py TERRASHADE_BIN SOURCE_DIR [--seconds S] [--seed N] [--timeout T]
                   [--commands info,render,...] [--replay 'ARGS...'] [--keep]
Environment: TERRASHADE_CLI_FUZZ_SECONDS (default 60) and TERRASHADE_CLI_FUZZ_SEED (default 31;
"random" for a new one, printed) override the defaults, for longer runs and replays. Exit status 0 if every
invocation passed, 1 with each finding (its seed, command line and what went wrong) otherwise.
Dependency-free: Python 3 standard library only.
"""
import argparse
import hashlib
import os
import random
import re
import shlex
import shutil
import signal
import stat
import struct
import subprocess
import sys
import tempfile
import time

# Commands and how much of the budget each gets (the bench studies only lightly).
COMMANDS = ["info", "hillshade", "visibility", "sun", "render", "relight", "spheres", "tiles", "plan", "insolation",
            "merge", "devices", "fly"]
BENCH_WEIGHT = 0.15
ALLOWED_EXITS = {0, 2, 130, 143}

# ---------------------------------------------------------------------------------------------
# Inputs


def write_geotiff(path, width, height, heights, lon0=5.70, lat0=45.25, cell=0.002):
    """A minimal float32 GeoTIFF (one strip, EPSG:4326, PixelIsArea) written by hand."""
    data = struct.pack("<%df" % (width * height), *heights)
    entries = []  # (tag, type, count, value bytes)

    def short(tag, v):
        entries.append((tag, 3, 1, struct.pack("<HH", v, 0)))

    def long_(tag, v):
        entries.append((tag, 4, 1, struct.pack("<I", v)))

    short(256, width)
    short(257, height)
    short(258, 32)  # bits per sample
    short(259, 1)  # no compression
    short(262, 1)  # min-is-black
    long_(273, 0)  # strip offset, patched below
    short(277, 1)
    short(278, height)
    long_(279, len(data))
    short(284, 1)
    short(339, 3)  # IEEE float
    doubles = {33550: [cell, cell, 0.0], 33922: [0.0, 0.0, 0.0, lon0, lat0, 0.0]}
    geokeys = [1, 1, 0, 3, 1024, 0, 1, 2, 1025, 0, 1, 1, 2048, 0, 1, 4326]
    extra = b""
    n_entries = len(entries) + 3
    ifd_size = 2 + 12 * n_entries + 4
    base = 8 + ifd_size
    blobs = []
    for tag, vals in sorted(doubles.items()):
        blob = struct.pack("<%dd" % len(vals), *vals)
        blobs.append((tag, 12, len(vals), base + len(extra)))
        extra += blob
    gk = struct.pack("<%dH" % len(geokeys), *geokeys)
    blobs.append((34735, 3, len(geokeys), base + len(extra)))
    extra += gk
    strip_offset = base + len(extra)
    out_entries = []
    for tag, typ, count, value in entries:
        if tag == 273:
            value = struct.pack("<I", strip_offset)
        out_entries.append((tag, typ, count, value))
    for tag, typ, count, off in blobs:
        out_entries.append((tag, typ, count, struct.pack("<I", off)))
    out_entries.sort()
    ifd = struct.pack("<H", len(out_entries))
    for tag, typ, count, value in out_entries:
        ifd += struct.pack("<HHI", tag, typ, count) + value
    ifd += struct.pack("<I", 0)
    with open(path, "wb") as f:
        f.write(b"II*\x00" + struct.pack("<I", 8) + ifd + extra + data)


def synthetic_heights(w, h, seed):
    import math
    rnd = random.Random(seed)
    bumps = [(rnd.uniform(0, w), rnd.uniform(0, h), rnd.uniform(3, w / 3), rnd.uniform(-300, 900)) for _ in range(6)]
    out = []
    for r in range(h):
        for c in range(w):
            z = 400.0 + 20 * math.sin(c * 0.3) * math.cos(r * 0.2)
            for (bx, by, s, a) in bumps:
                z += a * math.exp(-((c - bx) ** 2 + (r - by) ** 2) / (2 * s * s))
            out.append(z)
    return out


def make_inputs(folder, source_dir):
    """The read-only inputs every invocation may name; returns {kind: [paths]}."""
    os.makedirs(folder)
    p = lambda name: os.path.join(folder, name)
    write_geotiff(p("dem64.tif"), 64, 64, synthetic_heights(64, 64, 1))
    write_geotiff(p("dem48x40.tif"), 48, 40, synthetic_heights(48, 40, 2), lon0=5.828, lat0=45.25)
    shutil.copy(os.path.join(source_dir, "data", "grenoble_500px.tif"), p("grenoble.tif"))
    shutil.copy(os.path.join(source_dir, "data", "sunset_synthetic.hdr"), p("sky.hdr"))
    mesh_dir = os.path.join(source_dir, "tests", "fuzz", "corpus", "mesh_file")
    for name in ("tri.ac", "quad.obj", "tri.glb"):
        if os.path.exists(os.path.join(mesh_dir, name)):
            shutil.copy(os.path.join(mesh_dir, name), p(name))
    with open(p("binary.bin"), "wb") as f:
        f.write(bytes(random.Random(7).randrange(256) for _ in range(4096)))
    open(p("empty.tif"), "wb").close()
    with open(p("text.txt"), "w") as f:
        f.write("not a DEM\n" * 10)
    with open(p("times.txt"), "w") as f:
        f.write("2025-06-21T06:00Z\n2025-06-21T12:00Z\n")
    with open(p("path.csv"), "w") as f:
        f.write("lon,lat,height_m\n5.71,45.26,3000\n5.75,45.29,3200\n5.79,45.30,3100\n")
    with open(p("truncated.tif"), "wb") as f:
        f.write(open(p("dem64.tif"), "rb").read()[:300])
    os.makedirs(p("a_folder"))
    with open(os.path.join(p("a_folder"), "x.txt"), "w") as f:
        f.write("x")
    dems = [p("dem64.tif"), p("dem48x40.tif")]
    return {
        "dem": dems,
        "big_dem": [p("grenoble.tif")],
        "bad_file": [p("binary.bin"), p("empty.tif"), p("text.txt"), p("truncated.tif"), p("a_folder"),
                     p("missing.tif"), "/dev/null", "/proc/self/status"],
        "sky": [p("sky.hdr")],
        "mesh": [p(n) for n in ("tri.ac", "quad.obj", "tri.glb") if os.path.exists(p(n))],
        "times": [p("times.txt")],
        "path": [p("path.csv")],
        "all": sorted(os.path.join(folder, n) for n in os.listdir(folder)),
    }


def lock_inputs(folder):
    for root, dirs, files in os.walk(folder):
        for f in files:
            os.chmod(os.path.join(root, f), 0o444)
    for root, dirs, files in os.walk(folder, topdown=False):
        for d in dirs:
            os.chmod(os.path.join(root, d), 0o555)
    os.chmod(folder, 0o555)


def unlock(folder):
    for root, dirs, files in os.walk(folder):
        os.chmod(root, 0o755)
        for f in files:
            try:
                os.chmod(os.path.join(root, f), 0o644)
            except OSError:
                pass


def snapshot(folder):
    """Every entry under folder with its type, size and content hash."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for d in dirs:
            out[os.path.relpath(os.path.join(root, d), folder)] = "dir"
        for f in files:
            full = os.path.join(root, f)
            try:
                with open(full, "rb") as fh:
                    out[os.path.relpath(full, folder)] = hashlib.sha256(fh.read()).hexdigest()
            except OSError as e:
                out[os.path.relpath(full, folder)] = "unreadable %s" % e
    return out


# ---------------------------------------------------------------------------------------------
# The grammar: each command's --help


class Option:
    def __init__(self, names, type_, choices, required, multi):
        self.names, self.type, self.choices, self.required, self.multi = names, type_, choices, required, multi

    @property
    def long(self):
        longs = [n for n in self.names if n.startswith("--")]
        return longs[0] if longs else self.names[0]

    def __repr__(self):
        return "Option(%s %s %s%s)" % (self.names, self.type, self.choices or "", " REQUIRED" if self.required else "")


class Command:
    def __init__(self, path):
        self.path = path  # ["render"] or ["bench", "tiles"]
        self.options = []
        self.positionals = []  # Option with names = [name]
        self.subcommands = []


TYPE_RE = re.compile(r"^(TEXT|INT|UINT|FLOAT|NUMBER|BOOLEAN|ENUM|PATH|FILE|DIR|\[[^\]]*\]|[A-Z][A-Z_:]*)")


def parse_help(text):
    """Options, positionals and subcommands from CLI11's help text."""
    options, positionals, subcommands = [], [], []
    section = None
    for raw in text.splitlines():
        if not raw.strip():
            continue
        if not raw.startswith(" "):
            head = raw.strip().rstrip(":").lower()
            section = "options" if head.startswith("options") or head.startswith("flags") else \
                "positionals" if head.startswith("positionals") else \
                "subcommands" if head.startswith("subcommands") else None
            continue
        line = raw.strip()
        if section == "subcommands":
            name = line.split()[0]
            if re.match(r"^[a-z][a-z0-9_-]*$", name):
                subcommands.append(name)
            continue
        if section == "options" and line.startswith("-"):
            spec = re.split(r"\s{2,}", line)[0]
            tokens = spec.split()
            # A flag's default shows as --name{false}.
            names = [re.sub(r"\{.*", "", n) for n in tokens[0].split(",") if n.startswith("-")]
            rest = " ".join(tokens[1:])
            if "--help" in names or "--version" in names or "--help-all" in names:
                continue
            options.append(make_option(names, rest))
        elif section == "positionals":
            spec = re.split(r"\s{2,}", line)[0]
            tokens = spec.split()
            if tokens and re.match(r"^[a-zA-Z_][\w-]*$", tokens[0]):
                positionals.append(make_option([tokens[0]], " ".join(tokens[1:])))
    return options, positionals, subcommands


def make_option(names, rest):
    choices = None
    m = re.search(r":\{([^}]*)\}", rest)
    if m:
        choices = [c.strip() for c in m.group(1).split(",") if c.strip()]
    tm = re.match(r"^([A-Z]+)", rest)
    type_ = tm.group(1) if tm else None
    if type_ in ("REQUIRED", "Excludes", "Needs"):
        type_ = None
    if type_ == "ENUM":
        type_ = "TEXT"
    required = "REQUIRED" in rest.split()
    multi = "..." in rest or re.search(r"x\s*\d+|\[[^\]]*\]\s*\.\.\.", rest) is not None
    return Option(names, type_, choices, required, multi)


def discover(binary, env):
    """Every command (and bench subcommand) with its options, from --help."""
    def help_of(path):
        r = subprocess.run([binary] + path + ["--help"], capture_output=True, text=True, env=env, timeout=60)
        return r.stdout + r.stderr

    root_opts, _, root_subs = parse_help(help_of([]))
    commands = []
    for name in root_subs:
        cmd = Command([name])
        cmd.options, cmd.positionals, subs = parse_help(help_of([name]))
        for sub in subs:
            c = Command([name, sub])
            c.options, c.positionals, _ = parse_help(help_of([name, sub]))
            cmd.subcommands.append(c)
        commands.append(cmd)
    return commands


# ---------------------------------------------------------------------------------------------
# Values

NASTY_NUMBERS = ["-1", "0", "-0", "1e308", "-1e308", "1e999", "nan", "NaN", "inf", "-inf", "2147483648",
                 "4294967296", "9223372036854775808", "-2147483649", "1e-320", "0x10", "1,5", "3.5", "",
                 "abc", " ", "--", "1e", "-", "+5", "99999999999999999999999"]
NASTY_TEXT = ["", " ", "-", "--", "\t", "a" * 300, "%s%n%x", "../../../../etc/passwd", "é", "1,2,3,4,5,6,7,8",
              "nan,nan", "inf,0", "0,0,0,0", "-1", "1e999", ",", ":", "/", "auto", "none", "\x7f"]

INPUT_WORDS = ("dem", "dems", "input", "inputs", "albedo", "materials", "sky", "path", "mesh", "times", "shards",
               "file", "land-cover", "landcover", "orthophoto", "hdr", "in", "mosaic", "model")
OUTPUT_WORDS = ("out", "output", "csv", "json", "reference-out", "preview", "debug", "report", "plot", "log")


def is_output(opt):
    name = opt.long.lstrip("-")
    return name in OUTPUT_WORDS or name.endswith("-out") or name.startswith("out") or name.endswith("-csv") \
        or name.endswith("-json") or name == "o"


def is_input(opt):
    name = opt.long.lstrip("-").lower()
    if opt.type in ("FILE", "PATH", "DIR"):
        return True
    if opt.type in ("INT", "UINT", "FLOAT", "NUMBER") or opt.choices:
        return False
    return any(w == name or name.startswith(w + "-") or name.endswith("-" + w) for w in INPUT_WORDS)


# Valid command lines of the commands whose required options depend on each other, so that a
# share of the invocations does real work ({dem}, {mesh}: inputs; outputs in the working folder).
BASELINES = {
    "hillshade": ["{dem}", "--out", "o.png"],
    "visibility": ["{dem}", "--svf", "o.tif", "--directions", "8"],
    "render": ["{dem}", "--size", "48x48", "--time", "2025-06-21T12:00Z", "--directions", "4", "--out", "o.png"],
    "relight": ["{dem}", "--times", "2025-06-21T06:00Z/2025-06-21T18:00Z/PT6H", "--exposure", "13", "--directions",
                "4", "--out", "frames"],
    "tiles": ["{dem}", "--zoom", "9-10", "--out", "t"],
    "spheres": ["{mesh}", "--out", "s.json"],
    "sun": ["--lon", "5.7", "--lat", "45.2", "--time", "2025-06-21T12:00Z"],
    "info": ["{dem}"],
    "plan": ["tiles", "{dem}", "--zoom", "8-10"],
    "fly": ["{dem}", "--frames", "2", "--out", "f"],
    "insolation": ["{dem}", "--from", "2025-06-01", "--to", "2025-06-02", "--by", "day", "--directions", "8",
                   "--out", "i.tif"],
}


class Generator:
    def __init__(self, rnd, inputs, work):
        self.r, self.inputs, self.work = rnd, inputs, work
        self.outputs = []  # top-level names in the working directory the command was given

    def output_path(self, opt):
        r = self.r
        if r.random() < 0.06:
            # The classic mistakes: an input as the output, the inputs' folder, odd paths.
            return r.choice(self.inputs["dem"] + self.inputs["all"] + [os.path.dirname(self.inputs["dem"][0]),
                                                                     ".", "", "/", "/dev/null", "/proc/self/x"])
        name = r.choice(["o.png", "o.tif", "o.exr", "o.jpg", "o", "o/", "frames", "o.mbtiles", "o.csv", "o.json",
                         "sub/dir/o.png", "o.png.png", "O.PNG", "x", "t.png"])
        if opt.long in ("--out", "-o") and r.random() < 0.5:
            name = r.choice(["out.png", "out.tif", "out", "out.mbtiles", "out.csv"])
        top = name.split("/")[0]
        if top:
            self.outputs.append(top)
        return name

    def input_path(self, opt):
        r = self.r
        name = opt.long.lstrip("-").lower()
        kind = "dem"
        for key in ("sky", "mesh", "times", "path"):
            if key in name:
                kind = key
        if "albedo" in name or "ortho" in name or "materials" in name or "land" in name:
            kind = "dem"
        roll = r.random()
        if roll < 0.85 and self.inputs.get(kind):
            return r.choice(self.inputs[kind])
        if roll < 0.9:
            return r.choice(self.inputs["big_dem"])
        return r.choice(self.inputs["bad_file"] + self.inputs["all"])

    def number(self, opt, integer):
        r = self.r
        if r.random() < 0.12:
            return r.choice(NASTY_NUMBERS)
        name = opt.long
        if integer:
            if any(k in name for k in ("size", "width", "height", "texels", "frames", "samples", "rays")):
                return str(r.choice([1, 2, 8, 16, 32, 48, 64, 65, 100]))
            if "thread" in name:
                return str(r.choice([0, 1, 2]))
            return str(r.choice([0, 1, 2, 3, 4, 8, 16, 64, -1]))
        if "elevation" in name or "altitude" in name:
            return repr(r.choice([-10.0, 0.0, 5.0, 30.0, 45.0, 89.9, 90.0, 91.0]))
        if "azimuth" in name:
            return repr(r.choice([0.0, 90.0, 315.0, 359.9, 360.0, -45.0, 400.0]))
        return repr(r.choice([0.0, 0.001, 0.5, 1.0, 1.5, 2.0, 10.0, 100.0, -1.0, 1e6]))

    def text(self, opt):
        r = self.r
        if r.random() < 0.1:
            return r.choice(NASTY_TEXT)
        name = opt.long.lstrip("-")
        table = {
            "zoom": ["8", "8-9", "0-2", "9-8", "30", "8-", "-1", "a-b", "10"],
            "time": ["2025-06-21T12:00Z", "2025-06-21T06:00:00+02:00", "2025-13-40T25:00Z", "now", "2025-06-21"],
            "times": ["2025-06-21T05:00Z/2025-06-21T17:00Z/PT6H", "2025-06-21T05:00Z/2025-06-21T17:00Z/PT0H",
                      "2025-06-21T17:00Z/2025-06-21T05:00Z/PT1H", "2025-06-21T05:00Z/P1Y/PT1S"],
            "crop": ["5.71,45.26,5.76,45.30", "5.75,45.3,5.7,45.2", "0,0,1,1", "5.7,45.2", "nan,45,6,46"],
            "extent": ["5.71,45.26,5.76,45.30", "5,45,6,95", "0,0,0,0", "1e9,1e9,2e9,2e9"],
            "size": ["64x64", "64x48", "1x1", "0x0", "64x", "100000x100000", "-5x5", "64"],
            "hpr": ["0,0,0", "90,0,0", "0,90", "nan,0,0", "1,2,3,4"],
            "at": ["5.74,45.28", "5.74,45.28,100", "200,100", ""],
            "camera": ["5.72,45.25,2500", "5.72,45.25", "5.72,45.25,-100"],
            "look-at": ["5.75,45.28,1000", "5.75,45.28"],
            "shard": ["0/1", "1/3", "3/3", "0/0", "-1/2", "a/b", "1"],
            "device": ["cpu", "auto", "vulkan", "0", "7", "gpu"],
            "styles": ["hillshade", "hillshade,relief", "nope"],
            "sky": ["clear", "overcast", "hdr", "physical", "physical:scattering=single,turbidity=2"],
            "name": ["n", "", "x" * 200],
            "exaggeration": ["auto", "1", "0", "-1", "nan"],
        }
        for key, values in table.items():
            if name == key or name.endswith("-" + key) or name.startswith(key):
                return r.choice(values)
        return r.choice(["1", "2", "0", "a", "5.74,45.28", "1,2", "8-9", "64", "auto", "none", "cpu"])

    def value(self, opt):
        r = self.r
        if is_output(opt):
            return self.output_path(opt)
        if is_input(opt):
            return self.input_path(opt)
        if opt.choices and r.random() < 0.85:
            return r.choice(opt.choices)
        if opt.type in ("INT", "UINT"):
            return self.number(opt, True)
        if opt.type in ("FLOAT", "NUMBER"):
            return self.number(opt, False)
        return self.text(opt)

    def baseline(self, cmd):
        """A valid line of `cmd` with up to two more options of valid values, or None."""
        r = self.r
        base = BASELINES.get(cmd.path[0]) if len(cmd.path) == 1 else None
        if base is None:
            return None
        self.outputs = []
        args = [cmd.path[0]] + [a.format(dem=r.choice(self.inputs["dem"]), mesh=r.choice(self.inputs["mesh"] or ["-"]))
                                for a in base]
        extras = [o for o in cmd.options if not o.required and o.long not in args and not is_output(o)]
        r.shuffle(extras)
        for o in extras[: r.choice([0, 1, 1, 2])]:
            if o.type is None:
                args.append(o.long)
            elif o.choices:
                args += [o.long, r.choice(o.choices)]
            elif not is_input(o):
                args += [o.long, self.value(o)]
        return args

    def arguments(self, cmd):
        """One argument list for `cmd` (without the binary)."""
        r = self.r
        if r.random() < 0.3:
            line = self.baseline(cmd)
            if line is not None:
                return line
        args = list(cmd.path)
        self.outputs = []
        # Positionals: usually valid, sometimes missing, doubled or bad.
        for pos in cmd.positionals:
            if r.random() < 0.05:
                continue
            n = 1 if not pos.multi else r.choice([1, 1, 2, 3])
            for _ in range(n):
                if pos.names[0].lower() in ("dem", "dems", "input", "inputs", "file", "files", "mesh", "shards",
                                            "what"):
                    if cmd.path[0] == "merge":
                        args.append(r.choice(self.inputs["dem"] + self.inputs["bad_file"]))
                    elif "mesh" in pos.names[0]:
                        args.append(r.choice(self.inputs["mesh"] + self.inputs["bad_file"]))
                    else:
                        args.append(self.input_path(pos))
                elif pos.choices:
                    args.append(r.choice(pos.choices))
                else:
                    args.append(self.input_path(pos) if r.random() < 0.5 else self.text(pos))
        chosen = [o for o in cmd.options if o.required and r.random() < 0.95]
        extras = [o for o in cmd.options if not o.required]
        r.shuffle(extras)
        chosen += extras[: r.choice([0, 1, 2, 3, 4, 6])]
        # Keep real work small where the command takes a size.
        for o in cmd.options:
            if o.long in ("--size", "--threads", "--directions") and o not in chosen and r.random() < 0.6:
                chosen.append(o)
        for o in chosen:
            flag = o.long if r.random() < 0.8 or len(o.names) == 1 else r.choice(o.names)
            if o.type is None:
                args.append(flag)
                if r.random() < 0.05:
                    args.append(flag + "=" + r.choice(["true", "false", "2", "x"]))
                continue
            value = self.value(o)
            if o.long == "--size" and r.random() < 0.8:
                value = r.choice(["48x48", "64x64", "32x24"])
            if o.long == "--directions" and r.random() < 0.8:
                value = r.choice(["4", "8"])
            if r.random() < 0.15:
                args.append(flag + "=" + value)
            else:
                args += [flag, value]
            if o.multi and r.random() < 0.2:
                args.append(self.value(o))
        return self.mutate(cmd, args)

    def mutate(self, cmd, args):
        r = self.r
        head, rest = args[: len(cmd.path)], args[len(cmd.path):]
        for _ in range(r.choice([0, 0, 0, 0, 0, 1, 1, 2])):
            roll = r.random()
            if roll < 0.2 and rest:  # drop one
                del rest[r.randrange(len(rest))]
            elif roll < 0.35 and rest:  # duplicate one
                i = r.randrange(len(rest))
                rest.insert(r.randrange(len(rest) + 1), rest[i])
            elif roll < 0.5:  # unknown flag
                rest.insert(r.randrange(len(rest) + 1), r.choice(["--nope", "-Z", "--out-", "---", "-", "--=x"]))
            elif roll < 0.65 and rest:  # a value replaced by a nasty one
                rest[r.randrange(len(rest))] = r.choice(NASTY_TEXT + NASTY_NUMBERS)
            elif roll < 0.75 and rest:  # swap two
                i, j = r.randrange(len(rest)), r.randrange(len(rest))
                rest[i], rest[j] = rest[j], rest[i]
            elif roll < 0.85:  # an option of another command
                rest.append(r.choice(["--zoom", "--frames", "--times", "--resume", "--overwrite", "--shard", "-v"]))
                if r.random() < 0.6:
                    rest.append(r.choice(["1", "8-9", "0/2", "x"]))
            else:  # a value that is a path to a directory or binary file
                if rest:
                    rest[r.randrange(len(rest))] = r.choice(self.inputs["bad_file"])
        return head + rest


# ---------------------------------------------------------------------------------------------
# Running one invocation


def extra_limits():
    # A runaway allocation must not take the shared machine down; the product itself refuses
    # jobs above TERRASHADE_MEMORY_LIMIT before the work.
    import resource
    os.setsid()
    try:
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    except (ValueError, OSError):
        pass


def tmp_entries():
    try:
        return set(os.listdir("/tmp"))
    except OSError:
        return set()


def run_one(binary, args, work_root, inputs_dir, inputs_before, timeout, env_base, index, strict_messages=False,
            interrupt=None):
    """interrupt: None, or (delay in seconds, signal) to send the process once it has run that long."""
    cwd = os.path.join(work_root, "run%06d" % index)
    private = os.path.join(work_root, "private%06d" % index)
    os.makedirs(cwd)
    os.makedirs(os.path.join(private, "tmp"))
    os.makedirs(os.path.join(private, "home"))
    env = dict(env_base)
    env["TMPDIR"] = os.path.join(private, "tmp")
    env["HOME"] = os.path.join(private, "home")
    env["XDG_CACHE_HOME"] = os.path.join(private, "home", ".cache")
    tmp_before = tmp_entries()
    findings = []
    # A bench study runs for minutes by design and only its crashes count: it need not use a long
    # per-invocation bound, which would spend the budget on one study.
    if args and args[0] == "bench":
        timeout = min(timeout, 20.0)
    start = time.monotonic()
    proc = subprocess.Popen([binary] + args, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, preexec_fn=extra_limits)
    try:
        if interrupt is not None:
            try:
                out, err = proc.communicate(timeout=interrupt[0])
            except subprocess.TimeoutExpired:
                proc.send_signal(interrupt[1])
                out, err = proc.communicate(timeout=timeout)
        else:
            out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except OSError:
            pass
        out, err = proc.communicate()
        timed_out = True
        if args[0] != "bench":  # the studies run for minutes by design: only their crashes count
            findings.append("hang: no exit within %g s" % timeout)
    else:
        timed_out = False
    elapsed = time.monotonic() - start
    rc = proc.returncode
    err_text = err.decode("utf-8", "replace")
    # A signal sent before main() starts the interrupt watcher (the first ~30 ms: the loader and
    # static initialisers) kills the process the default way: nothing was written then, and the
    # checks below still hold it to that.
    killed_early = interrupt is not None and rc == -int(interrupt[1])
    if not timed_out and not killed_early:
        if rc < 0:
            findings.append("killed by signal %d (%s)" % (-rc, signal.Signals(-rc).name))
        elif rc not in ALLOWED_EXITS:
            findings.append("exit %d" % rc)
    # An input error is one line (the user guide's promise); --strict-messages makes more a finding.
    if strict_messages and rc == 2:
        lines = [l for l in err_text.replace("\r", "\n").splitlines() if l.strip()]
        if len(lines) != 1:
            findings.append("exit 2 with %d lines on stderr" % len(lines))
    # The inputs: byte for byte, nothing added or removed.
    # A file there named once on the command line was only an output (bench dem --out in/x.tif):
    # writing it is allowed; one named twice was read too.
    after = snapshot(inputs_dir)
    if after != inputs_before:
        changed = sorted(k for k in set(after) | set(inputs_before) if after.get(k) != inputs_before.get(k))

        def named(rel):
            full = os.path.join(inputs_dir, rel)
            return sum(a == full or a.endswith("=" + full) for a in args)
        over_inputs = [k for k in changed if named(k.split(os.sep)[0]) != 1]
        if over_inputs:
            findings.append("the inputs' folder changed: %s" % ", ".join(over_inputs[:8]))
    # The working directory: only what the command line named.
    allowed = set()
    for a in args:
        for piece in a.split("="):
            if piece and not piece.startswith("/") and not piece.startswith(".."):
                top = piece.split("/")[0]
                if top not in ("", "."):
                    allowed.add(top)
                    allowed.add(top + ".shards")  # slurm-style work folders named after the output
    # CLI11 takes "-o=x" as the value "=x" and "--out --flag=v" as the folder "--flag=v": still names
    # given on the command line.
    stray = [e for e in os.listdir(cwd) if e not in allowed and not any(e in a for a in args)]
    if stray:
        findings.append("wrote outside its outputs (in the working directory): %s" % ", ".join(sorted(stray)[:8]))
    leftover_tmp = os.listdir(env["TMPDIR"])
    if leftover_tmp:
        findings.append("left files in TMPDIR: %s" % ", ".join(sorted(leftover_tmp)[:8]))
    home_entries = []
    for root, dirs, files in os.walk(env["HOME"]):
        rel = os.path.relpath(root, env["HOME"])
        # terrashade's sphere cache, and Mesa's shader cache (lavapipe's, not ours).
        if rel.startswith(os.path.join(".cache", "terrashade")) or rel.startswith(os.path.join(".cache", "mesa")):
            continue
        home_entries += [os.path.join(rel, f) for f in files]
    if home_entries:
        findings.append("wrote into HOME: %s" % ", ".join(sorted(home_entries)[:8]))
    # Other processes use /tmp too (a second fuzzer, other tests): only entries naming this pid.
    new_tmp = [e for e in tmp_entries() - tmp_before if str(proc.pid) in e]
    if new_tmp:
        findings.append("left entries in /tmp: %s" % ", ".join(sorted(new_tmp)[:8]))
    # A probe for symlink escapes: nothing in the working directory may point outside it.
    return findings, rc, elapsed, err_text, cwd, private


def command_line(args, inputs_dir):
    """The invocation as a shell line, the inputs' folder written $IN (what --replay takes)."""
    return "terrashade " + " ".join(shlex.quote(a).replace(inputs_dir, "$IN") for a in args)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("source_dir")
    ap.add_argument("--seconds", type=float, default=float(os.environ.get("TERRASHADE_CLI_FUZZ_SECONDS", 60)))
    ap.add_argument("--seed", type=int, default=None)
    ap.add_argument("--timeout", type=float, default=20.0)
    ap.add_argument("--commands", default="")
    ap.add_argument("--replay", default=None, help="one argument list (shell words) to run once and check")
    ap.add_argument("--keep", action="store_true", help="keep the working folders")
    ap.add_argument("--max-findings", type=int, default=20)
    ap.add_argument("--signals", type=float, default=0.0,
                    help="the share of invocations sent SIGINT or SIGTERM after 0.02-1 s (then: exit 130/143, nothing left)")
    ap.add_argument("--strict-messages", action="store_true", help="exit 2 with other than one stderr line is a finding")
    ap.add_argument("--log", default=None, help="a file getting every invocation: exit code, line, first stderr line")
    opts = ap.parse_args()
    binary = os.path.realpath(opts.binary)
    seed = opts.seed
    if seed is None:
        env_seed = os.environ.get("TERRASHADE_CLI_FUZZ_SEED", "31")
        seed = random.SystemRandom().randrange(1, 2 ** 31) if env_seed == "random" else int(env_seed)
    print("cli_fuzz: seed %d (replay: TERRASHADE_CLI_FUZZ_SEED=%d), %g s budget, %g s per invocation"
          % (seed, seed, opts.seconds, opts.timeout), flush=True)

    env_base = {k: v for k, v in os.environ.items()
                if not k.startswith("SLURM_") and k not in ("JOB_COMPLETION_INDEX", "DISPLAY", "WAYLAND_DISPLAY")}
    env_base["TERRASHADE_MEMORY_LIMIT"] = env_base.get("TERRASHADE_MEMORY_LIMIT", "3GB")
    env_base["LC_ALL"] = "C"

    work_root = tempfile.mkdtemp(prefix="terrashade-cli-fuzz.")
    inputs_dir = os.path.join(work_root, "in")
    findings_total = []
    count = 0
    exits = {}
    try:
        inputs = make_inputs(inputs_dir, opts.source_dir)
        lock_inputs(inputs_dir)
        inputs_before = snapshot(inputs_dir)
        if opts.replay is not None:
            replay = opts.replay.strip()
            if replay.startswith("terrashade "):
                replay = replay[len("terrashade "):]
            plan = [[a.replace("$IN", inputs_dir) for a in shlex.split(replay)]]
        else:
            plan = None
            commands = discover(binary, env_base)
            wanted = [c for c in opts.commands.split(",") if c]
            commands = [c for c in commands if not wanted or c.path[0] in wanted]
            if not commands:
                print("cli_fuzz: no command found in --help", file=sys.stderr)
                return 1
            print("cli_fuzz: %d commands, %d options parsed from --help" % (
                len(commands), sum(len(c.options) + sum(len(s.options) for s in c.subcommands) for c in commands)),
                flush=True)
        rnd = random.Random(seed)
        gen = Generator(rnd, inputs, work_root)
        deadline = time.monotonic() + opts.seconds
        index = 0
        while True:
            if plan is not None:
                if index >= len(plan):
                    break
                args = plan[index]
            else:
                if time.monotonic() >= deadline:
                    break
                cmd = rnd.choice(commands)
                if cmd.subcommands:
                    if rnd.random() > BENCH_WEIGHT:
                        continue
                    cmd = rnd.choice(cmd.subcommands)
                if cmd.path[0] == "fly" and rnd.random() < 0.9:
                    # No display here: fly renders --frames offscreen.
                    args = gen.arguments(cmd)
                    if "--frames" not in args:
                        args += ["--frames", rnd.choice(["1", "2", "0", "-1", "x"])]
                else:
                    args = gen.arguments(cmd)
            index += 1
            interrupt = None
            if opts.signals > 0 and rnd.random() < opts.signals:
                interrupt = (round(rnd.uniform(0.02, 1.0), 2), rnd.choice([signal.SIGINT, signal.SIGTERM]))
            findings, rc, elapsed, err, cwd, private = run_one(binary, args, work_root, inputs_dir, inputs_before,
                                                               opts.timeout, env_base, index, opts.strict_messages,
                                                               interrupt)
            if interrupt is not None and findings:
                findings.append("after %s at %.2f s" % (signal.Signals(interrupt[1]).name, interrupt[0]))
            count += 1
            exits[rc] = exits.get(rc, 0) + 1
            if opts.log:
                with open(opts.log, "a") as log:
                    first = err.strip().splitlines()[0] if err.strip() else ""
                    log.write("%d\t%.1f\t%s\t%s\n" % (rc, elapsed, command_line(args, inputs_dir), first))
            if snapshot(inputs_dir) != inputs_before:
                # The inputs are the reference for every later run: make them again.
                unlock(inputs_dir)
                shutil.rmtree(inputs_dir)
                inputs = make_inputs(inputs_dir, opts.source_dir)
                gen.inputs = inputs
                lock_inputs(inputs_dir)
                inputs_before = snapshot(inputs_dir)
            if findings:
                report = "FINDING (seed %d, invocation %d, %.1f s): %s\n  %s\n  stderr: %s" % (
                    seed, index, elapsed, "; ".join(findings), command_line(args, inputs_dir),
                    err.strip().replace("\n", "\n          ")[-1500:])
                print(report, flush=True)
                findings_total.append(report)
                if len(findings_total) >= opts.max_findings:
                    break
            if not opts.keep:
                unlock(cwd)
                shutil.rmtree(cwd, ignore_errors=True)
                shutil.rmtree(private, ignore_errors=True)
    finally:
        if not opts.keep:
            unlock(work_root)
            shutil.rmtree(work_root, ignore_errors=True)
        else:
            print("cli_fuzz: kept %s" % work_root)
    print("cli_fuzz: %d invocations, exit codes %s, %d findings (seed %d)" % (
        count, ", ".join("%s: %d" % (k, v) for k, v in sorted(exits.items())), len(findings_total), seed), flush=True)
    return 1 if findings_total else 0


if __name__ == "__main__":
    sys.exit(main())
