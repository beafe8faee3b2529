# Shell functions shared by the whole-render benchmark scripts (sourced, not run).

# best_of N DIR COMMAND...: the shortest wall-clock time of N runs of COMMAND in DIR, in seconds
# (its standard output is discarded; what it says on standard error shows).
best_of() {
    local runs=$1 dir=$2 best="" start end
    shift 2
    for ((k = 0; k < runs; ++k)); do
        start=$(date +%s.%N)
        (cd "$dir" && "$@" > /dev/null)
        end=$(date +%s.%N)
        best=$(awk -v a="$start" -v b="$end" -v best="$best" \
            'BEGIN { d = b - a; if (best == "" || d < best) best = d; printf "%.3f", best }')
    done
    echo "$best"
}

# machine_line: the machine and its load average, the first line of every results table.
machine_line() {
    echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)," \
         "load $(cut -d' ' -f1-3 /proc/loadavg)"
}
