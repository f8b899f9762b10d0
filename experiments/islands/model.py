#!/usr/bin/env python3
"""Run-time model of the island ES for P = 64..1024 ranks (one island per rank, one core each).

Per stored generation, on the critical path (every rank waits for rank 0 at the next generation):
  T_gen(P) = lambda * t_eval                       every island evaluates its offspring
           + alpha * log2(P) + P * mu * b / beta   gather of all islands' populations at rank 0
           + (alpha + K * b / beta) / G            ring migration, every G generations
           + c_commit + 2 * P * mu * c_row         rank 0 stores P island rows + the archipelago's
Evaluations/s = P * lambda / T_gen(P); efficiency = (P * lambda / T_gen) / (P / t_eval).

Measured here (README.md says how): t_eval (CPU per evaluation), b (bytes per migrant / stored
member), c_commit and c_row (SQLite, WAL, synchronous=FULL, one transaction per generation).
Assumed (not measurable on one machine): alpha = 2 us latency, beta = 5 GB/s (an InfiniBand
class interconnect), and 50 us latency / 1 GB/s for 10 Gbit Ethernet.
"""
import math

MU, LAMBDA, K, G = 10, 40, 2, 5
B = 230            # bytes per individual on the wire (genotype ~130 B, steps, 3 objectives, score)
C_COMMIT = 0.010   # s per stored generation (fsync)
C_ROW = 45e-6      # s per stored row
T_EVALS = {"cup (wall distances), 77 us CPU": 77e-6, "plate (t2d temperatures), ~17 ms": 17e-3}
NETS = {"InfiniBand-class (2 us, 5 GB/s)": (2e-6, 5e9), "10 GbE (50 us, 1 GB/s)": (50e-6, 1e9)}


def t_gen(p, t_eval, alpha, beta, store=True):
    comm = alpha * math.log2(p) + p * MU * B / beta + (alpha + K * B / beta) / G
    return LAMBDA * t_eval + comm + ((C_COMMIT + 2 * p * MU * C_ROW) if store else 0)


print("| evaluation | network | P | T_gen (s) | evals/s | efficiency | without the per-generation store: efficiency |")
print("|---|---|---|---|---|---|---|")
for name, t in T_EVALS.items():
    for net, (alpha, beta) in NETS.items():
        for p in (64, 128, 256, 512, 1024):
            tg = t_gen(p, t, alpha, beta)
            rate = p * LAMBDA / tg
            eff = rate / (p / t)
            eff_ns = (p * LAMBDA / t_gen(p, t, alpha, beta, store=False)) / (p / t)
            print(f"| {name} | {net} | {p} | {tg:.4g} | {rate:.3g} | {eff:.1%} | {eff_ns:.1%} |")
