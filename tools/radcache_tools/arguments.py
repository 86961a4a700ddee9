"""The tools' command lines: argument types (argparse refuses a value of the wrong kind with one
line naming the option, and exit status 2), and what stands after `--`, passed to every radcache
render as it is."""

import argparse


def positive_int(text):
    """An integer of at least 1 (a size, a count)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not an integer" % text)
    if value < 1:
        raise argparse.ArgumentTypeError("%d is not positive" % value)
    return value


def positive_seconds(text):
    """A time budget in seconds, above 0."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a number of seconds" % text)
    if not value > 0.0:
        raise argparse.ArgumentTypeError("%r is not above 0 seconds" % text)
    return value


def frame_range(text):
    """Frames A:B (integers, A <= B), kept as the text radcache's --frames takes."""
    parts = text.split(":")
    try:
        first, last = (int(x) for x in parts)
    except ValueError:
        raise argparse.ArgumentTypeError("expected A:B (two frame numbers), got %r" % text)
    if last < first:
        raise argparse.ArgumentTypeError("%r ends before it starts" % text)
    return text


def parse_with_extra(parser, argv):
    """(parser's arguments from argv before `--`, the list of what follows `--`, [] without)."""
    if "--" not in argv:
        return parser.parse_args(argv), []
    split = argv.index("--")
    return parser.parse_args(argv[:split]), argv[split + 1:]
