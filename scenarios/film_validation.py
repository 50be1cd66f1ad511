"""Film operator validation: the finite-volume Reynolds operator against closed forms.

    transient run scenarios/film_validation.py [--quick] [--out DIR] [--no-plot]

Sommerfeld long bearing (pressure profile, grid convergence on uniform and stretched grids), the short
full-film bearing against Ocvirk's limit, the squeeze film between rectangular plates against its series
(transient.study.film_validation). Writes film_validation.png, .json (all numbers) and .csv (one row per
solve) into DIR (default transient_out/film_validation/). --quick: coarse grids, a few seconds.
"""

from __future__ import annotations

import sys
from pathlib import Path

from transient.study.film_validation import FULL, QUICK, run_validation  # noqa: F401  (QUICK: the test's settings)
from transient.study.scenario import parser

DEFAULT_OUT = Path(__file__).resolve().parent / "out" / "film_validation"


def _summary(res) -> str:
    lines = ["", "check                         case               errors (coarse .. fine)          orders"]
    for kind, s in res["sommerfeld"].items():
        lines.append(f"Sommerfeld max p error        {kind:18s} {s['p_err'][0]:.3e} .. {s['p_err'][-1]:.3e}"
                     f"         {' '.join(f'{o:.2f}' for o in s['orders'])}")
    for kind, s in res["sommerfeld"].items():
        lines.append(f"Sommerfeld force error        {kind:18s} {s['fy_err'][0]:.3e} .. {s['fy_err'][-1]:.3e}")
    sb = res["short_bearing"]
    lines.append(f"short bearing Fy error        L/D {'/'.join(str(x) for x in sb['L_over_D']):14s} "
                 f"{' '.join(f'{e:.3e}' for e in sb['fy_err'])}  "
                 f"{' '.join(f'{o:.2f}' for o in sb['orders_in_L_over_D'])} (in L/D)")
    for label, s in res["squeeze"].items():
        lines.append(f"squeeze load error            {label:18s} {s['err'][0]:.3e} .. {s['err'][-1]:.3e}"
                     f"         {' '.join(f'{o:.2f}' for o in s['orders'])}")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = parser(__doc__, DEFAULT_OUT)
    ap.add_argument("--no-plot", action="store_true", help="numbers only, no figure")
    a = ap.parse_args(argv)
    if not a.out.strip():
        ap.error("--out must be a non-empty directory path")
    out = Path(a.out)
    if out.exists() and not out.is_dir():
        ap.error(f"--out must be a directory, but {out} is a file")
    settings = QUICK if a.quick else FULL
    res = run_validation(out, make_plot=not a.no_plot, **settings)
    print(_summary(res))
    print(f"\nwall time {res['wall_time_s']:.1f} s")
    for kind, p in res["files"].items():
        print(f"written: {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
