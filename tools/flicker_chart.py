#!/usr/bin/env python3
"""Per-frame error and flicker of rendered frame sequences over a clip, as a chart.

For each labelled sequence, `radcache compare --frames A:B TEST#### REF####` gives every frame's
relMSE against its reference and the temporal error of every pair of consecutive frames (the
change between frames against the same change in the references; docs/path-tracer.md,
"Flicker"). The chart draws both over the frames, one line per sequence, the means in the legend,
and the references' own share of each figure (what a perfect sequence would measure) as a dotted
grey line. A sequence is LABEL=TEST#### (compared here against --reference over --frames) or
LABEL=FILE.json (what `radcache compare --frames ... --json FILE.json` wrote).

  tools/flicker_chart.py --reference scenes/moving-light/reference/frame####.exr --frames 0:15 \\
      --out flicker.png "per-frame ic=ic/frame####.exr" "temporal ic=tic/frame####.exr"

Options: --aov NAME, --mask FILE, --reference-spp N (passed to compare), --net (net figures:
the references' noise subtracted), --title TEXT, --summary FILE.json (every sequence's per-frame
figures and means, and their ratios to the first sequence's), --keep DIR (keep compare's JSON).
Prints one line per sequence: mean relMSE, mean temporal error, and their ratios to the first
sequence's. The radcache executable is $RADCACHE, else build/radcache. Needs matplotlib
(tools/requirements.txt).
"""

import argparse
import json
import os
import re
import sys
import tempfile

from radcache_tools import radcache
FRAMES_FORM = re.compile(r"^(-?\d+):(-?\d+)$")


class ChartError(Exception):
    """Bad input: the message names the option, sequence or file; exit status 2, or 1 for a
    failed comparison."""

    def __init__(self, message, status=2):
        super().__init__(message)
        self.status = status


def parse_sequence(text):
    """LABEL=SOURCE -> (label, source)."""
    label, equals, source = text.partition("=")
    if not equals or not label.strip() or not source:
        raise ChartError("sequence '%s': expected LABEL=TEST#### or LABEL=FILE.json" % text)
    return label.strip(), source


def compare_sequence(label, pattern, args, json_path):
    """Runs radcache compare --frames over one test sequence; its JSON."""
    if not args.reference or not args.frames:
        raise ChartError("sequence '%s': a TEST#### pattern needs --reference and --frames" %
                         label)
    command = ["compare", "--frames", args.frames, pattern, args.reference,
               "--aov", args.aov, "--json", json_path]
    if args.mask:
        command += ["--mask", args.mask]
    if args.reference_spp:
        command += ["--reference-spp", str(args.reference_spp)]
    result = radcache.attempt(command)
    if result.returncode != 0:
        lines = (result.stderr or result.stdout).strip().splitlines()
        raise ChartError("sequence '%s': %s" % (label, lines[-1] if lines else "compare failed"),
                         result.returncode)
    return read_compare_json(label, json_path)


def read_compare_json(label, path):
    try:
        with open(path) as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        raise ChartError("sequence '%s': %s" % (label, e), 1)
    if not isinstance(report, dict) or "frames" not in report or "mean" not in report:
        raise ChartError("sequence '%s': %s is not the JSON of radcache compare --frames" %
                         (label, path), 1)
    return report


def series(report, key):
    """(frames, values) of one per-frame figure, skipping frames without it (the first frame's
    temporal error)."""
    frames, values = [], []
    for row in report["frames"]:
        if row.get(key) is not None:
            frames.append(row["frame"])
            values.append(row[key])
    return frames, values


def figure_keys(net):
    """The per-frame keys drawn in the two panels, and their means' keys."""
    if net:
        return ("relmse_net", "temporal_error_net")
    return ("relmse", "temporal_error")


def check_net(sequences, net):
    for label, report in sequences:
        for key in figure_keys(net):
            if report["mean"].get(key) is None:
                raise ChartError("sequence '%s': no %s (the references' noise is unknown: give "
                                 "--reference-spp, or references with a stddev layer and their "
                                 "records)" % (label, key))


def draw(sequences, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    keys = figure_keys(args.net)
    noise_keys = ("reference_noise", "temporal_reference_noise")
    noise_labels = ("references' own noise",
                    "references' own noise (frames taken as independent: an upper bound)")
    titles = ("relMSE per frame", "temporal error per frame (frames f-1, f)")
    figure, axes = plt.subplots(2, 1, figsize=(8, 7), dpi=110, sharex=True)
    for panel, key, noise_key, noise_label, title in zip(axes, keys, noise_keys, noise_labels,
                                                          titles):
        positive = True
        for index, (label, report) in enumerate(sequences):
            frames, values = series(report, key)
            mean = report["mean"].get(key)
            legend = "%s (mean %.3g)" % (label, mean) if mean is not None else label
            panel.plot(frames, values, marker="o", markersize=3, label=legend,
                       color="C%d" % (index % 10))
            positive = positive and all(v > 0 for v in values)
        # The references' own share: what a perfect sequence would measure (not with --net,
        # where it is subtracted).
        if not args.net:
            frames, values = series(sequences[0][1], noise_key)
            if values:
                panel.plot(frames, values, linestyle=":", color="grey", label=noise_label)
                positive = positive and all(v > 0 for v in values)
        if positive:
            panel.set_yscale("log")
        panel.set_ylabel(key)
        panel.set_title(title + (", net of the references' noise" if args.net else ""))
        panel.grid(True, which="both", alpha=0.3)
        panel.legend(fontsize=8)
    axes[-1].set_xlabel("frame")
    axes[-1].xaxis.set_major_locator(MaxNLocator(integer=True))
    aov = sequences[0][1].get("aov", args.aov)
    figure.suptitle(args.title or "error and flicker over the clip (%s)" % aov)
    figure.tight_layout()
    figure.savefig(args.out)
    plt.close(figure)


def summary(sequences, net):
    """Every sequence's means and per-frame figures, and the ratios of its means to the first
    sequence's (first / this: above 1 where this one is better)."""
    relmse_key, temporal_key = figure_keys(net)
    first = sequences[0][1]["mean"]
    rows = []
    for label, report in sequences:
        mean = report["mean"]
        row = {"label": label, "aov": report.get("aov"), "test": report.get("test"),
               "reference": report.get("reference"), "mean": mean,
               "frames": [{k: f.get(k) for k in ("frame", "relmse", "relmse_net",
                                                   "reference_noise", "temporal_error",
                                                   "temporal_error_net",
                                                   "temporal_reference_noise")}
                          for f in report["frames"]]}
        for key in (relmse_key, temporal_key):
            ok = mean.get(key) and first.get(key) is not None
            row["first_over_this_" + key] = first[key] / mean[key] if ok else None
        rows.append(row)
    return {"figures": [relmse_key, temporal_key], "sequences": rows}


def print_summary(report):
    relmse_key, temporal_key = report["figures"]
    print("%-28s %12s %12s %10s %10s" % ("sequence", "mean " + relmse_key[:10],
                                          "mean " + temporal_key[:10], "rel ratio",
                                          "temp ratio"))
    for row in report["sequences"]:
        def text(value, form):
            return form % value if value is not None else "-"
        print("%-28s %12s %12s %10s %10s" % (
            row["label"][:28], text(row["mean"].get(relmse_key), "%.4g"),
            text(row["mean"].get(temporal_key), "%.4g"),
            text(row["first_over_this_" + relmse_key], "%.3g"),
            text(row["first_over_this_" + temporal_key], "%.3g")))
    print("(ratios: the first sequence's mean over this one's)")


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sequences", nargs="+", metavar="LABEL=SOURCE",
                        help="LABEL=TEST#### (compared with --reference) or LABEL=FILE.json")
    parser.add_argument("--out", required=True, help="the chart (.png, .pdf, .svg)")
    parser.add_argument("--reference", help="reference frames, REF#### (for TEST#### sequences)")
    parser.add_argument("--frames", help="A:B, the frames to compare (for TEST#### sequences)")
    parser.add_argument("--aov", default="beauty", help="layer to compare (default beauty)")
    parser.add_argument("--mask", help="compare's --mask: FILE, or FILE#### one per frame")
    parser.add_argument("--reference-spp", type=int,
                        help="samples per pixel of the references (default: their records)")
    parser.add_argument("--net", action="store_true",
                        help="draw the figures net of the references' noise")
    parser.add_argument("--title", help="the chart's title")
    parser.add_argument("--summary", help="write the figures and means as JSON")
    parser.add_argument("--keep", help="keep compare's JSON of every sequence in this folder")
    args = parser.parse_args(argv)
    if args.frames is not None:
        match = FRAMES_FORM.match(args.frames)
        if not match or int(match.group(2)) <= int(match.group(1)):
            raise ChartError("--frames: expected A:B with B > A, got '%s'" % args.frames)
    if args.reference_spp is not None and args.reference_spp < 1:
        raise ChartError("--reference-spp: expected a positive integer, got %d" %
                         args.reference_spp)
    if os.path.splitext(args.out)[1].lower() not in (".png", ".pdf", ".svg"):
        raise ChartError("--out %s: expected a .png, .pdf or .svg name" % args.out)
    for path, option in ((args.out, "--out"), (args.summary, "--summary")):
        if path and not os.path.isdir(os.path.dirname(os.path.abspath(path))):
            raise ChartError("%s %s: no such folder" % (option, path))
    return args


def load_sequences(args, scratch):
    sequences = []
    for index, text in enumerate(args.sequences):
        label, source = parse_sequence(text)
        if label in [s[0] for s in sequences]:
            raise ChartError("sequence '%s' given twice" % label)
        if source.endswith(".json"):
            report = read_compare_json(label, source)
        else:
            report = compare_sequence(label, source, args,
                                      os.path.join(scratch, "sequence%02d.json" % index))
        sequences.append((label, report))
    return sequences


def main(argv):
    try:
        args = parse_arguments(argv)
        if not os.access(radcache.executable(), os.X_OK) and any(
                not parse_sequence(s)[1].endswith(".json") for s in args.sequences):
            raise ChartError("build radcache first: %s is missing" % radcache.executable(), 1)
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
        with tempfile.TemporaryDirectory() as scratch:
            sequences = load_sequences(args, args.keep or scratch)
            check_net(sequences, args.net)
            report = summary(sequences, args.net)
            draw(sequences, args)
        if args.summary:
            with open(args.summary, "w") as f:
                json.dump(report, f, indent=2)
                f.write("\n")
        print_summary(report)
        print("wrote %s" % args.out)
    except ChartError as e:
        print("flicker_chart: %s" % e, file=sys.stderr)
        return e.status
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
