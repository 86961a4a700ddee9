"""The tools' command lines: what stands after `--` is passed to every radcache render as it is."""


def parse_with_extra(parser, argv):
    """(parser's arguments from argv before `--`, the list of what follows `--`, [] without)."""
    if "--" not in argv:
        return parser.parse_args(argv), []
    split = argv.index("--")
    return parser.parse_args(argv[:split]), argv[split + 1:]
