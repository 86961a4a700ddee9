"""Which curve wins at a time budget (a library of tools/results.py): for each budget, the lowest
relMSE and the lowest FLIP that any curve of a sweep reached within it, over the points measured
(no curve is extrapolated past its longest run: a budget beyond every run gets the best of what
was measured, and says so)."""

BUDGETS = [10.0, 100.0, 1000.0]


def number(value, digits=3):
    return "" if value in ("", None) else "%.*g" % (digits, value)


def best_within(rows, key, budget):
    """The row with the lowest `key` among those whose time fits the budget, or None."""
    fitting = [r for r in rows if r.get(key) not in ("", None) and r["render_seconds"] <= budget]
    return min(fitting, key=lambda r: r[key]) if fitting else None


def cell(row, key):
    if row is None:
        return "nothing measured within it"
    return "%s (%s, %s s): %s" % (row["curve"], row["setting"], number(row["render_seconds"]),
                                 number(row[key]))


def winners_lines(report):
    """One scene's rows of the winners table."""
    rows = report["rows"]
    longest = max((r["render_seconds"] for r in rows), default=0.0)
    lines = []
    for budget in BUDGETS:
        note = "" if budget <= longest else " (longest run %s s)" % number(longest)
        lines.append("| %s | %g s%s | %s | %s |" % (
            report["scene"], budget, note, cell(best_within(rows, "relmse", budget), "relmse"),
            cell(best_within(rows, "flip", budget), "flip")))
    return lines


def winners_section(per_scene):
    """The section over every scene (per_scene: each scene's winners_lines)."""
    if not per_scene:
        return []
    return ["## Which curve wins at 10 s, 100 s and 1000 s", "",
            "For each scene and time budget, the curve that reached the lowest image relMSE and "
            "the one that reached the lowest FLIP within that time, over the points of the "
            "sweeps below (times as in each table: radcache's render phase, `+oidn` with the "
            "denoise step, Mitsuba's `mi.render`). No curve is extrapolated past its longest "
            "run: where a budget exceeds every run, the entry is the best of what was measured "
            "and the budget names the longest run.", "",
            "| scene | budget | lowest relMSE | lowest FLIP |", "| --- | --- | --- | --- |"] + [
            line for lines in per_scene for line in lines] + [""]
