"""tools/sweep.py's methods and quality knobs, read from radcache's option tables: the methods
and their knobs from `radcache render --list-knobs --json` (the registry's order), the options
each method's table declares (knob or not) from `radcache reference`; the checks of the sweep's
curated ladders against them, and --ladder METHOD:OPTION[=V1,V2,...]: one curve of a method with
one of its knobs taking each value in turn, the values given or generated from the knob's
default, direction and range."""

import collections
import json
import math
import os
import re
import tempfile

from radcache_tools import radcache

# Values of a generated ladder: the default and 3 steps towards accuracy.
LADDER_STEPS = 4
# A step of a generated ladder: the factor for an "increase" knob, the divisor for a "decrease" one.
INCREASE_STEP = 2.0
DECREASE_STEP = 1.5
LADDER_FORM = re.compile(r"^([\w-]+):(?:--)?([\w-]+)(?:=(.*))?$")
METHOD_SECTION = re.compile(r"^### `--method (\S+)`")
OPTION_ROW = re.compile(r"^\| `(--[\w-]+)")
AUTO_GRID = re.compile(r"^auto\*\d+(\.\d+)?$")

# knobs: method -> {option: its knob entry}, in the registry's order; declared: method -> the
# options its table declares.
Tables = collections.namedtuple("Tables", "knobs declared")
# One curve: `name` as the sweep calls it (a method, or a variant such as ic-ivg), rendered with
# --method `method` and `flags`, `option` (a knob, `knob` its table entry) taking each of `values`.
Ladder = collections.namedtuple("Ladder", "spec name method flags option knob values")


class KnobError(Exception):
    """Bad input or a drift between the sweep and the tables: one line, what to fix."""


def declared_options(reference):
    """method -> the options of its table, from the "### `--method NAME`" sections of
    `radcache reference` (docs/command-line.md)."""
    declared, method = {}, None
    for line in reference.splitlines():
        section = METHOD_SECTION.match(line)
        if section:
            method = section.group(1)
            declared[method] = set()
        elif line.startswith("#"):
            method = None
        elif method and OPTION_ROW.match(line):
            declared[method].add(OPTION_ROW.match(line).group(1))
    return declared


def read_tables(run_radcache):
    """The tables through `run_radcache(arguments) -> stdout`, once at start."""
    listing = json.loads(run_radcache(["render", "--list-knobs", "--json"]))
    knobs = collections.OrderedDict(
        (entry["method"], collections.OrderedDict((k["name"], k) for k in entry["knobs"]))
        for entry in listing)
    return Tables(knobs, declared_options(run_radcache(["reference"])))


def check_curated(name, method, varies, sets, tables):
    """A curated ladder `name` renders `method`, varies the options `varies` (each must be a
    quality knob of the method's table) and sets `sets` (each must be an option of it)."""
    if method not in tables.knobs:
        raise KnobError("the sweep's %s curves render --method %s, which radcache's registry does "
                        "not have (%s)" % (name, method, ", ".join(tables.knobs)))
    for option in varies:
        if option not in tables.knobs[method]:
            raise KnobError("%s: the sweep varies %s, which %s's option table does not mark a "
                            "quality knob (radcache render --method %s --list-knobs)" % (
                                name, option, method, method))
    for option in sets:
        if option not in tables.declared.get(method, ()):
            raise KnobError("%s: the sweep sets %s, which %s's option table does not declare "
                            "(radcache reference)" % (name, option, method))


def number(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def refusal(knob):
    """Why no ladder can be generated for a knob, or None."""
    if knob["type"] == "choice":
        return None
    if knob.get("default_note"):
        return "its default depends on other options (%s)" % knob["default_note"]
    if knob["type"] not in ("integer", "number"):
        return "a %s knob has no generated ladder" % knob["type"]
    if number(knob["default"]) is None:
        return "its default '%s' is not a number" % knob["default"]
    return None


def generated_values(knob):
    """LADDER_STEPS values from the default towards accuracy (x2 a step for an "increase" knob,
    /1.5 for a "decrease" one), clamped to [min, max], de-duplicated; a choice knob's choices."""
    if knob["type"] == "choice":
        return list(knob["choices"])
    step = INCREASE_STEP if knob["knob"] == "increase" else 1.0 / DECREASE_STEP
    values = []
    for k in range(LADDER_STEPS):
        value = number(knob["default"]) * step ** k
        value = min(max(value, knob.get("min", -math.inf)), knob.get("max", math.inf))
        text = str(int(round(value))) if knob["type"] == "integer" else "%.3g" % value
        if text not in values:
            values.append(text)
    return values


def knob_names(tables, method):
    return ", ".join(tables.knobs[method]) or "none"


def ladder(spec, tables, variants):
    """The Ladder of `--ladder spec`; `variants`: name -> (method, flags) of the sweep's
    variants."""
    found = LADDER_FORM.match(spec)
    if not found:
        raise KnobError("--ladder %s: expected METHOD:OPTION or METHOD:OPTION=V1,V2,... (e.g. "
                        "ic:--ic-rays=256,1024,4096)" % spec)
    name, option, given = found.group(1), "--" + found.group(2), found.group(3)
    method, flags = variants.get(name, (name, []))
    if method not in tables.knobs:
        raise KnobError("--ladder %s: unknown method '%s' (radcache's methods: %s; variants: %s)"
                        % (spec, name, ", ".join(tables.knobs), ", ".join(variants) or "none"))
    knob = tables.knobs[method].get(option)
    if knob is None:
        raise KnobError("--ladder %s: %s is not a quality knob of %s (%s's knobs: %s)" % (
            spec, option, name, method, knob_names(tables, method)))
    if given is not None:
        values = given.split(",")
        if "" in values:
            raise KnobError("--ladder %s: an empty value" % spec)
    elif refusal(knob):
        raise KnobError("--ladder %s: %s; give its values: %s:%s=V1,V2,..." % (
            spec, refusal(knob), name, option))
    else:
        values = generated_values(knob)
    return Ladder(spec, name, method, flags, option, knob, values)


def generated_ladders(name, method, flags, tables):
    """A method without curated curves: a generated ladder of each knob that has one."""
    return [Ladder("%s:%s" % (name, option), name, method, flags, option, knob,
                   generated_values(knob))
            for option, knob in tables.knobs[method].items() if not refusal(knob)]


def check_values(ladders, options):
    """radcache's own parser checks each ladder's values (ranges, forms, the rules between
    options) before anything renders: `render` of a scene that does not exist parses and checks
    the whole command line first and exits 2 on a bad one (docs/option-tables.md, "Errors"). An
    auto*K grid is checked as auto."""
    with tempfile.TemporaryDirectory(prefix="sweep-check-") as folder:
        scene = os.path.join(folder, "no-scene.json")
        for one in ladders:
            for value in one.values:
                parsed = "auto" if AUTO_GRID.match(value) else value
                result = radcache.attempt(
                    ["render", scene, "-o", os.path.join(folder, "no-image.exr"), "--method",
                     one.method] + one.flags + [one.option, parsed] + options)
                if result.returncode == 2:
                    line = (result.stderr.strip().splitlines() or ["exit status 2"])[-1]
                    raise KnobError("--ladder %s: radcache refuses %s %s: %s" % (
                        one.spec, one.option, value, line.replace("radcache: error: ", "")))
