"""Seed 000 Fig. 5.2: the Maugis-Dugdale impact loss over the JKR loss versus the
Tabor parameter Λ (log axis), with the case boundaries Λ1, Λ2 and the Λ = 4
("μ ≈ 5, taken as JKR") mark. Writes loss_vs_lambda.png (or the path given).

    python examples/loss_vs_lambda.py [out.png]      (needs matplotlib)
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import tabor  # noqa: E402

LAMBDA_1 = (3 * np.pi**3 / 1024) ** (1 / 3)  # case 1 | case 2 (5.42)
LAMBDA_2 = (3 * np.pi**4 / (512 * (np.pi - 1))) ** (1 / 3)  # case 2 | case 3 (5.46), K = 1


def main(out="loss_vs_lambda.png"):
    lam = np.geomspace(0.05, 100.0, 2000)
    ratio = tabor.maugis_dugdale_loss(lam) / tabor.jkr_normalized_loss()  # 2000 direct evaluations
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=150)
    ax.semilogx(lam, ratio, color="C0", lw=2, label=r"Maugis-Dugdale $W(\Lambda)/W_\mathrm{JKR}$")
    ax.axhline(1.0, color="0.4", lw=1, ls="--", label="JKR limit")
    for x, name in ((LAMBDA_1, r"$\Lambda_1$"), (LAMBDA_2, r"$\Lambda_2$")):
        ax.axvline(x, color="0.7", lw=0.8)
        ax.text(x, 1.03, name, ha="center", va="bottom", fontsize=9)
    r4 = tabor.maugis_dugdale_loss(4.0) / tabor.jkr_normalized_loss()
    ax.plot([4.0], [r4], "o", color="C3")
    ax.annotate(rf"$\Lambda=4$ ($\mu\approx5$): {r4:.3f}", (4.0, r4), (6.0, 0.7),
                arrowprops=dict(arrowstyle="->", color="C3"), color="C3", fontsize=9)
    ax.set_xlabel(r"Tabor parameter $\Lambda = d_n/h$")
    ax.set_ylabel(r"$|\Delta U_\mathrm{kin}| \,/\, |\Delta U_\mathrm{kin}^\mathrm{JKR}|$")
    ax.set_ylim(0, 1.1)
    ax.set_xlim(lam[0], lam[-1])
    ax.set_title("Adhesive loss of a Maugis-Dugdale impact (seed 000, Fig. 5.2)", fontsize=10)
    ax.legend(loc="lower right", fontsize=9)
    ax.grid(True, which="both", alpha=0.25)
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
