"""tools/sweep.py's charts and HTML page: log-log error against the median render time, each point
with a horizontal bar from the fastest to the slowest of its repeats, the Pareto front over the
medians, and equal-time crops beside the reference's. Needs numpy, matplotlib and flip-evaluator
(tools/requirements.txt)."""

import html
import math
import os

METHOD_COLOURS = {"pt": "tab:blue", "ic": "tab:orange", "ic-ivg": "tab:brown", "ivg": "tab:purple",
                  "ivg-gather": "tab:red", "povray": "tab:green", "mitsuba": "tab:olive"}
# A denoised curve (METHOD+oidn, tools/sweep_peers.py) takes its method's colour.
DENOISED = "+oidn"


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def pareto_front(points):
    """The points (time, error) not beaten in both time and error by another, by time."""
    front = []
    for t, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((t, e))
    return front


def time_spread(rows):
    """Matplotlib's xerr for rows: distances from the median render time down to the fastest
    repeat and up to the slowest (0 where a row has no spread, e.g. a peer's single run)."""
    below, above = [], []
    for r in rows:
        t = r["render_seconds"]
        fastest = r.get("render_seconds_min")
        slowest = r.get("render_seconds_max")
        below.append(t - fastest if fastest not in ("", None) else 0.0)
        above.append(slowest - t if slowest not in ("", None) else 0.0)
    return [below, above]


def curve_order(points):
    curves = []
    for r in points:
        if r["curve"] not in curves:
            curves.append(r["curve"])
    return curves


def method_colour(method):
    return METHOD_COLOURS.get(method[:-len(DENOISED)] if method.endswith(DENOISED) else method)


def draw_chart(rows, key, title, path, label="relMSE"):
    """Writes the chart of column `key` against render time; False when no row has it."""
    plt = pyplot()
    points = [r for r in rows if r.get(key) not in ("", None) and r[key] > 0]
    if not points:
        return False
    figure, axes = plt.subplots(figsize=(7, 5), dpi=110)
    markers = "osD^v<>p*h"
    styles = ["-", ":", "-.", (0, (5, 1))]
    seen = {}
    for i, curve in enumerate(curve_order(points)):
        members = sorted((r for r in points if r["curve"] == curve),
                         key=lambda r: r["render_seconds"])
        method = members[0]["method"]
        # Curves of one method share its colour and differ by line style; a denoised curve is
        # always dashed.
        style = "--" if method.endswith(DENOISED) else styles[seen.get(method, 0) % len(styles)]
        seen[method] = seen.get(method, 0) + 1
        axes.errorbar([r["render_seconds"] for r in members], [r[key] for r in members],
                      xerr=time_spread(members), marker=markers[i % len(markers)],
                      color=method_colour(method), linestyle=style, capsize=2,
                      elinewidth=0.8, label=curve)
    front = pareto_front([(r["render_seconds"], r[key]) for r in points])
    axes.plot([t for t, _ in front], [e for _, e in front], color="black", linestyle="--",
              linewidth=1, zorder=0, label="Pareto front")
    axes.scatter([t for t, _ in front], [e for _, e in front], s=120, facecolors="none",
                 edgecolors="black", linewidths=1, zorder=3)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("render time (s): median of the repeats, bar from fastest to slowest")
    axes.set_ylabel(label)
    axes.set_title(title)
    axes.grid(True, which="both", alpha=0.3)
    if len(curve_order(points)) > 8:  # many curves (peers, +oidn): the legend beside the axes
        figure.set_size_inches(10, 5)
        axes.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    else:
        axes.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)
    return True


def exr_reader():
    """flip-evaluator's EXR reader, None when the package is not installed."""
    try:
        import flip_evaluator
    except ImportError:
        return None
    return flip_evaluator.load


def tonemapped(path):
    load = exr_reader()
    import numpy
    image = numpy.clip(load(path), 0.0, 1.0)
    return numpy.where(image <= 0.0031308, 12.92 * image,
                       1.055 * numpy.power(image, 1.0 / 2.4) - 0.055)


def crop_box(width, height, crop):
    if crop:
        x, y, w, h = crop
    else:  # the middle half of the image
        x, y, w, h = width // 4, height // 4, max(1, width // 2), max(1, height // 2)
    return x, y, min(w, width - x), min(h, height - y)


def save_crop(source, path, box):
    x, y, w, h = box
    pyplot().imsave(path, source[y:y + h, x:x + w])


def equal_time_rows(rows):
    """One row per curve: the run whose median time is nearest (log scale) to the median of all."""
    times = sorted(r["render_seconds"] for r in rows)
    target = times[len(times) // 2]
    chosen = {}
    for r in rows:
        distance = abs(math.log(r["render_seconds"] / target))
        if r["curve"] not in chosen or distance < chosen[r["curve"]][0]:
            chosen[r["curve"]] = (distance, r)
    return target, [r for _, r in chosen.values()]


def cell(value):
    return html.escape(("%.4g" % value) if isinstance(value, float) else str(value))


def equal_time_crops(report, out, crop):
    """The equal-time section: crops of the reference and of each curve's run nearest in time."""
    if exr_reader() is None:
        return ("<h2>Equal time</h2><p>No crops: reading the EXR images needs flip-evaluator "
                "(tools/requirements.txt), which is not installed.</p>")
    rows = report["rows"]
    reference = tonemapped(report["reference"])
    height, width = reference.shape[:2]
    box = crop_box(width, height, crop)
    save_crop(reference, os.path.join(out, "reference.crop.png"), box)
    target, chosen = equal_time_rows(rows)
    cells = []
    for r in chosen:
        name = os.path.splitext(r["image"])[0]
        save_crop(tonemapped(os.path.join(out, r["image"])), os.path.join(out, name + ".crop.png"),
                  box)
        save_crop(pyplot().imread(os.path.join(out, name + ".error.png"))[..., :3],
                  os.path.join(out, name + ".error.crop.png"), box)
        cells.append(
            "<td><b>%s</b><br>%s<br>%.3g s, relMSE %.3g, FLIP %.3g<br>"
            "<img src='%s'><br><img src='%s'></td>" %
            (html.escape(r["curve"]), html.escape(r["setting"]), r["render_seconds"], r["relmse"],
             r["flip"], html.escape(name + ".crop.png"), html.escape(name + ".error.crop.png")))
    return """<h2>Equal time (about {target:.3g} s)</h2>
<p>Crop x={x} y={y} {w}x{h} of each curve's run nearest in time; below each, its relMSE per pixel
(log10 from -5, black, to 0, white).</p>
<table><tr><td><b>reference</b><br><img src="reference.crop.png"></td>{cells}</tr></table>
""".format(target=target, x=box[0], y=box[1], w=box[2], h=box[3], cells="".join(cells))


def write_html(report, out, crop):
    rows = report["rows"]
    columns = report["columns"]
    charts = "".join("<img src='%s'>" % c for c in report["charts"])
    table = "".join("<tr>%s</tr>" % "".join("<td>%s</td>" % cell(r[c]) for c in columns)
                    for r in rows)
    page = """<!doctype html><meta charset="utf-8"><title>radcache sweep: {scene}</title>
<style>body{{font-family:sans-serif}} td{{vertical-align:top;padding:4px}}
img{{image-rendering:pixelated;max-width:100%}}</style>
<h1>{scene}</h1><p>{when}, {device}, git {git}. Reference: {reference}. Time axis: {timing}</p>
<p>Command: <code>{command}</code></p>{charts}
{crops}<h2>All runs</h2><table border=1 cellspacing=0><tr>{header}</tr>{table}</table>
""".format(scene=html.escape(report["scene"]), when=report["date"],
           device=html.escape(report["device"]), git=report["git"],
           reference=html.escape(report["reference"]), timing=html.escape(report["timing"]),
           command=html.escape(report["command"]), charts=charts,
           crops=equal_time_crops(report, out, crop), header="".join("<th>%s</th>" % c for c in columns), table=table)
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page)
