# Shared by scripts/test_all.sh and scripts/test_integrations.sh (sourced): run named steps,
# count them, go on after a failure. The caller sets passed=0 failed=0 failed_steps=().

section() {
    printf '\n==================== %s ====================\n' "$1"
}

# step TITLE FUNCTION: runs FUNCTION with `set -e` in a subshell, records the outcome and
# goes on, so one failure does not hide the others.
step() {
    local title="$1"
    shift
    section "$title"
    local t0=$SECONDS
    set +e
    (set -e; "$@")
    local rc=$?
    if [ $rc -eq 0 ]; then
        passed=$((passed + 1))
        echo "--> ok: $title ($((SECONDS - t0)) s)"
    else
        failed=$((failed + 1))
        failed_steps+=("$title")
        echo "--> FAILED (exit $rc): $title ($((SECONDS - t0)) s)"
    fi
}
