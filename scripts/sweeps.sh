#!/usr/bin/env bash
# The statistical sweeps that run by hand (BENCHMARKS.md, "Statistical sweeps by hand"): the
# full χ² sweep of the samplers and the full χ² grid of the BSDFs, the `--ignored` tests of
# tests/chi2.rs and tests/bsdf.rs. About 4 + 2.5 minutes on two cores; they left .ci/run when
# its total neared the 20-minute budget. The default run (`cargo test --workspace --release`)
# keeps a χ² test of every sampler and BSDF. --workspace: the same feature set as the default
# run, so nothing is rebuilt.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "== [${SECONDS} s] full χ² sweep of the samplers"
cargo test --workspace --release --test chi2 -- --ignored --test-threads 1 \
  --skip visible_mixture_posterior_sampler_full --skip family_sweep --skip student_t_heavy_tail_visible
echo "== [${SECONDS} s] full χ² grid of the BSDFs (every NDF × α × θo × η × iso/aniso)"
cargo test --workspace --release --test bsdf -- --ignored --test-threads 2
echo "== [${SECONDS} s] sweeps passed"
