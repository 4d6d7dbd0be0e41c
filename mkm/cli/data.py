"""``mkm data``: the published measurements shipped with the package, listed or copied into a
folder of the user's, so that ``mkm import`` of them works from a wheel (no source tree)."""

from __future__ import annotations

EXAMPLE = ("example: mkm data copy martens_boblan_2017_forcemaps.csv; then mkm import "
           "martens_boblan_2017_forcemaps.csv --id dmsp-20 --D0 20 --t0 1.8 --muscle "
           "\"Festo DMSP-20-300\"")


def register(subparsers) -> None:
    data = subparsers.add_parser(
        "data", help="published measurements shipped with mkm: list them, copy one to import it",
        description="Tables of forces measured by other labs and published, shipped with the "
        "package byte for byte (each file's # header holds its provenance): `list` names them "
        "with their installed paths, `path NAME` prints one's path, `copy NAME [TO]` writes it "
        "into the working folder (or TO, a file or a folder; an existing file is kept) for "
        "mkm import.", epilog=EXAMPLE)
    sub = data.add_subparsers(dest="data_command", required=True, metavar="ACTION")
    listing = sub.add_parser("list", help="the shipped tables and their installed paths",
                             description="Each shipped table's file name and installed path, "
                             "one a line, separated by a tab.", epilog="example: mkm data list")
    listing.set_defaults(func=_list)
    path = sub.add_parser("path", help="the installed path of one shipped table",
                          description="The installed path of the shipped table NAME (read it "
                          "there; copy it to import it: mkm data copy).",
                          epilog="example: mkm data path martens_boblan_2017_forcemaps.csv")
    path.add_argument("name", help="the table's file name (mkm data list)")
    path.set_defaults(func=_path)
    copy = sub.add_parser("copy", help="copy a shipped table into a folder of yours",
                          description="Copy a shipped table byte for byte (its SHA-256, which "
                          "mkm import records, stays the published one) and print its path.",
                          epilog=EXAMPLE)
    copy.add_argument("name", help="the table's file name (mkm data list)")
    copy.add_argument("to", nargs="?", default=None,
                      help="a file name ending as the table's (.csv) or an existing folder to "
                      "write it into (default: the working folder)")
    copy.set_defaults(func=_copy)


def _list(args) -> int:
    from mkm.paths import published_tables

    for name, path in published_tables().items():
        print(f"{name}\t{path}")
    return 0


def _path(args) -> int:
    from mkm.paths import published_table

    print(published_table(args.name))
    return 0


def _copy(args) -> int:
    from mkm.cli.common import say
    from mkm.core.records import one_argument
    from mkm.paths import copy_published_table

    copied = copy_published_table(args.name, args.to)
    print(copied)
    # what a newcomer types next: the table holds several muscles, none of their walls
    say(args, "note", f"import it with mkm import {one_argument(copied)} --id ID --D0 MM --t0 "
        "MM --muscle NAME (its # header names its muscles and their geometry; the guide's run "
        "folders page gives the lines for each)")
    return 0
