#!/usr/bin/env bash
# A real run of a cdem ensemble on SLURM (single node, Debian's slurm-wlm and munge),
# compared with the same ensemble in one process. Run from the repository root as root:
#   scripts/slurm/ensemble-demo.sh [OUTDIR [CASE...]]
# CASE: lem, cdem (the 2026-12-01 record), slip (the slip-surface slope, 8 members,
# 2 array tasks), slip-srm (the same with cdem srm per member, 4 members); requeue (the
# cdem case with array task 0 killed by `scontrol requeue` once its journal holds a
# record: it runs again with --resume and the merged members.jsonl must be the
# one-process file, byte for byte); default all.
# Prints what references/ensemble.md records, with the load average before and after
# each case (the machine may be shared). Needs: cargo; installs slurm-wlm, munge.
set -euo pipefail
out=${1:-out/slurm-demo}
shift || true
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(lem cdem slip slip-srm requeue)
here=$(cd "$(dirname "$0")" && pwd)
"$here/single-node.sh" start >/dev/null
cargo build --release --quiet
export CDEM=$PWD/target/release/cdem
rm -rf "$out"
mkdir -p "$out"

run_case() { # name input members shards
    local name=$1 input=$2 members=$3 shards=$4 dir="$out/$1"
    mkdir -p "$dir"
    local t0 jid mid load0
    load0=$(cut -d' ' -f1-3 /proc/loadavg)
    t0=$(date +%s.%N)
    jid=$(sbatch --parsable --chdir="$PWD" --output="$dir/slurm-%A_%a.out" --array=0-$((shards - 1)) \
        "$here/ensemble.sbatch" "$input" "$members" "$dir" 1)
    mid=$(sbatch --parsable --chdir="$PWD" --output="$dir/merge-%j.out" --dependency=afterok:"$jid" \
        "$here/merge.sbatch" "$dir")
    while squeue -h -j "$jid,$mid" 2>/dev/null | grep -q .; do sleep 1; done
    local t1
    t1=$(date +%s.%N)
    local state
    state=$(scontrol show job "$mid" 2>/dev/null | grep -o 'JobState=[A-Z]*' || echo "JobState=(gone)")
    "$CDEM" ensemble "$input" --members "$members" --seed 1 --out "$dir/single" >/dev/null
    local t2
    t2=$(date +%s.%N)
    if cmp -s "$dir/merged/members.jsonl" "$dir/single/members.jsonl"; then same=identical; else same=DIFFER; fi
    printf '%s: %s, %d members, %d array tasks (job %s) + merge (job %s, %s): %.1f s; one process (%s threads): %.1f s; speed-up %.2f; members.jsonl %s (%s bytes); load average %s before, %s after\n' \
        "$name" "$input" "$members" "$shards" "$jid" "$mid" "$state" "$(echo "$t1 - $t0" | bc)" \
        "${RAYON_NUM_THREADS:-$(nproc)}" "$(echo "$t2 - $t1" | bc)" "$(echo "($t2 - $t1) / ($t1 - $t0)" | bc -l)" \
        "$same" "$(wc -c <"$dir/single/members.jsonl")" "$load0" "$(cut -d' ' -f1-3 /proc/loadavg)"
    grep -E "^Eq. 21 K|^- phase 2" "$dir/merged/ensemble.md" || true
    grep -E "^\| (mean FS|probability of failure)" "$dir/merged/ensemble.md" || true
    [ "$same" = identical ]
}

requeue_case() { # input members shards
    local input=$1 members=$2 shards=$3 dir="$out/requeue"
    mkdir -p "$dir"
    local jid mid journal="$dir/shard-0/members-0-of-$3.jsonl"
    jid=$(sbatch --parsable --chdir="$PWD" --output="$dir/slurm-%A_%a.out" --array=0-$((shards - 1)) \
        "$here/ensemble.sbatch" "$input" "$members" "$dir" 1)
    # Task 0 running with at least one record in its journal, not yet done.
    until [ -s "$journal" ] || ! squeue -h -j "${jid}_0" | grep -q .; do sleep 0.2; done
    local before
    before=$(wc -l <"$journal" 2>/dev/null || echo 0)
    scontrol requeue "${jid}_0"
    echo "requeue: task ${jid}_0 killed and requeued with $before of its records in its journal"
    mid=$(sbatch --parsable --chdir="$PWD" --output="$dir/merge-%j.out" --dependency=afterok:"$jid" \
        "$here/merge.sbatch" "$dir")
    while squeue -h -j "$jid,$mid" 2>/dev/null | grep -q .; do sleep 1; done
    "$CDEM" ensemble "$input" --members "$members" --seed 1 --out "$dir/single" >/dev/null
    local same
    if cmp -s "$dir/merged/members.jsonl" "$dir/single/members.jsonl"; then same=identical; else same=DIFFER; fi
    echo "requeue: task 0's log (its two starts):"
    grep -h -E "resum|journal|members" "$dir"/slurm-"${jid}"_0.out | head -5 || true
    echo "requeue: merged members.jsonl against one process: $same ($(wc -c <"$dir/single/members.jsonl") bytes)"
    [ "$same" = identical ]
}

echo "slurm: $(sinfo --version), node $(hostname -s) with $(nproc) CPUs; $(uptime)"
for c in "${cases[@]}"; do
    case $c in
    lem) run_case lem verification/ensemble/paper-slope-lem.toml 2000 4 ;;
    cdem) run_case cdem verification/cases/slope/slope.toml 12 3 ;;
    slip) run_case slip verification/ensemble/paper-slope-slip.toml 8 2 ;;
    slip-srm) run_case slip-srm verification/ensemble/paper-slope-slip-srm.toml 4 2 ;;
    requeue) requeue_case verification/cases/slope/slope.toml 12 3 ;;
    *)
        echo "unknown case $c (lem, cdem, slip, slip-srm, requeue)" >&2
        exit 2
        ;;
    esac
done
