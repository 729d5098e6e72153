#!/usr/bin/env python3
"""Runs `sgtllc eval` on sequences with configuration variants and prints a Markdown table.

Usage: bench/eval_study.py SGTLLC_BINARY SEQ_DIR [SEQ_DIR ...] [--variants NAME,NAME,...] [--threads N]

Each variant is a YAML fragment applied over the defaults (see VARIANTS). Used for the ablation and default-choice
tables in BENCHMARKS.md; needs only python3's standard library.
"""
import argparse
import json
import os
import subprocess
import tempfile

VARIANTS = {
    "default": "",
    "score paper": "verification: {score_formula: paper}",
    "score legacy": "verification: {score_formula: legacy}",
    "global G1": "descriptor: {global_mode: G1}",
    "global G3": "descriptor: {global_mode: G3}",
    "paper: G1 + score paper": "descriptor: {global_mode: G1}\nverification: {score_formula: paper}",
    "angle only": "descriptor: {kind: angle}",
    "length only": "descriptor: {kind: length}",
    "without v_i": "association: {entries: jk}",
    "without v_j": "association: {entries: ik}",
    "without v_k": "association: {entries: ij}",
    "without RANSAC": "verification: {use_ransac: false}",
}


def evaluate(binary, seq, fragment, threads):
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
        f.write(fragment + "\n")
        path = f.name
    try:
        out = subprocess.run([binary, "eval", seq, "--config", path, "--json", "--threads", str(threads)],
                             check=True, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    return json.loads(out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("sequences", nargs="+")
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    print("| sequence | variant | F1max | EP | R@100%P | retrieval R@15 | loops true / false | top-1 F1max |")
    print("|---|---|---|---|---|---|---|---|")
    for seq in args.sequences:
        for name in args.variants.split(","):
            m = evaluate(args.binary, seq, VARIANTS[name], args.threads)
            print(f"| {os.path.basename(seq.rstrip('/'))} | {name} | {m['f1_max']:.4f} | {m['ep']:.4f} | "
                  f"{m['recall_at_100_precision']:.4f} | {m['retrieval_recall_at_15']:.4f} | "
                  f"{m['loops']['true']} / {m['loops']['false']} | {m['top1']['f1_max']:.4f} |", flush=True)


if __name__ == "__main__":
    main()
