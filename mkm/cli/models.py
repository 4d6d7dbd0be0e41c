"""``mkm models``: every predictor the registry builds, with its parameters."""

from __future__ import annotations


def register(subparsers) -> None:
    models = subparsers.add_parser(
        "models", help="list every predictor name with its parameters (the spec syntax)",
        description="Every predictor that --model / --models accept, with its parameters.",
        epilog="example: mkm models; then mkm fem solve --model axisym:mesh=coarse --D0 35 "
        "--t0 2.5 --eps 0.05")
    models.set_defaults(func=_models)


def _models(args) -> int:
    from mkm.registry import describe

    print(describe())
    return 0
