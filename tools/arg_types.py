"""Argument types the tools share (a library, not a command): argparse refuses a value of the
wrong kind with one line naming the option, and exit status 2."""

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
