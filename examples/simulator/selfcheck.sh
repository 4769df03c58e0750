#!/usr/bin/env bash
# selfcheck.sh: checks the example simulators. Needs only g++ and python3 (and
# coreutils' timeout); builds into a temporary directory and leaves nothing behind.
#
#   examples/simulator/selfcheck.sh            # CXX=clang++ PYTHON=python3.12 also work
#
# (a) Table 2.1 through the protocol against the exercise's numbers; the mistake
#     examples of docs/checker.md; the template's public multi-step test; the
#     template's box-box examples (docs/references.md §2) through --trace.
# (b) the Python and the C++ simulator on the command files in commands/, correct and
#     with every --mistake, to 1e-9 relative; every mistake changes some answer.
# (c) the --fail modes, in both programs.
# (d) malformed input and bad options: exit 2 with a message naming the line/id.
# (e) tum_template_adapter.cpp built against template_stub/ gives the reference
#     simulator's numbers, and keeps the simulator's own stdout out of its answers.
# Exit status 0 when every check passes, 1 otherwise.
set -u
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
CXX=${CXX:-g++}
PYTHON=${PYTHON:-python3}
failures=0
ok() { echo "ok    $*"; }
bad() { echo "FAIL  $*"; failures=$((failures + 1)); }

flags=(-std=c++17 -O2 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off)
echo "building with $CXX into $tmp"
"$CXX" "${flags[@]}" "$here/reference_simulator.cpp" -o "$tmp/cpp" || { echo "FAIL  build reference_simulator"; exit 1; }
"$CXX" "${flags[@]}" -I"$here/template_stub" "$here/tum_template_adapter.cpp" \
    "$here/template_stub/RigidBodySystemSimulator.cpp" -o "$tmp/adapter" || { echo "FAIL  build adapter"; exit 1; }
cpp=("$tmp/cpp")
py=("$PYTHON" "$here/reference_simulator.py")
compare=("$PYTHON" "$here/compare_states.py")

# expect_numbers NAME FILE LINE TOL N1 N2 ...: the numbers on answer LINE of FILE
# (1-based) start with N1 N2 ... to TOL absolute.
expect_numbers() {
    local name=$1 file=$2 line=$3 tol=$4
    shift 4
    if "$PYTHON" - "$file" "$line" "$tol" "$@" <<'EOF'; then ok "$name"; else bad "$name"; fi
import sys
path, line, tol = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
want = [float(t) for t in sys.argv[4:]]
lines = [l.split() for l in open(path) if l.strip()]
got = [float(t) for t in lines[line - 1][:len(want)]] if len(lines) >= line else []
if len(got) != len(want) or any(abs(g - w) > tol for g, w in zip(got, want)):
    print("      want %s\n      got  %s" % (want, got))
    sys.exit(1)
EOF
}

echo "== (a) Table 2.1, the mistake examples, the template's tests"
t21="$here/commands/table-2-1.commands"
"${cpp[@]}" < "$t21" > "$tmp/t21.cpp"
"${py[@]}" < "$t21" > "$tmp/t21.py"
"${cpp[@]}" --float < "$t21" > "$tmp/t21.float"
# After the step: x = 0, v = (1, 1, 0), omega = (-2.4, 4.918033, -1.764706).
for variant in cpp py float; do
    tol=5e-7
    [ "$variant" = float ] && tol=2e-6
    expect_numbers "Table 2.1 ($variant): x, v, omega" "$tmp/t21.$variant" 1 "$tol" \
        0 0 0 1 1 0 -2.4 4.918033 -1.764706
done
# docs/checker.md's Table 2.1 examples of the mistake models.
mistake_example() {
    local id=$1 from=$2
    shift 2
    "${cpp[@]}" --mistake "$id" < "$t21" | cut -d' ' -f"$from"- > "$tmp/m.txt"
    expect_numbers "Table 2.1 --mistake $id" "$tmp/m.txt" 1 5e-7 "$@"
}
mistake_example velocity-before-position 1 2 2 0
mistake_example missing-time-step 4 0.5 0.5 0
mistake_example body-inverse-inertia 7 -4.918033 2.4 -1.764706
mistake_example inertia-not-inverted 7 -0.1041667 0.0508333 -0.0906667
mistake_example torque-reversed 7 2.4 -4.918033 1.764706
mistake_example half-extents-for-size 7 -9.6 19.672131 -7.058824
mistake_example omega-before-orientation 10 0.3349683 0.3050817 0.8866438 -0.0926508
# The template's public test TestRigidBodiesAfterForceApplication (answer 3 = body 0
# after 4 steps). December 2022 expectations: x = (-0.1, -0.2, 0.16), v = (0, 0, 0.2),
# omega = (5.8590, -2.1106, -1.1391), to 1e-4: only with R^T I0inv R. 2018: omega =
# (5.9064, -1.7891, -1.0204), also with the quaternion product the template then had.
pub="$here/commands/template-public-test.commands"
"${cpp[@]}" --mistake transposed-inertia < "$pub" > "$tmp/pub2022"
expect_numbers "template public test, 2022 numbers, --mistake transposed-inertia" "$tmp/pub2022" 3 1e-4 \
    -0.1 -0.2 0.16 0 0 0.2 5.8590 -2.1106 -1.1391
"${cpp[@]}" --mistake transposed-inertia --mistake quaternion-right-multiplied < "$pub" > "$tmp/pub2018"
expect_numbers "template public test, 2018 numbers, + quaternion-right-multiplied" "$tmp/pub2018" 3 1e-4 \
    -0.1 -0.2 0.16 0 0 0.2 5.9064 -1.7891 -1.0204
"${cpp[@]}" < "$pub" > "$tmp/pubstd"
if "$PYTHON" - "$tmp/pubstd" <<'EOF'; then ok "template public test: the standard R I0inv R^T fails both versions"; else bad "template public test: the standard form should fail it"; fi
import sys
w = [float(t) for t in open(sys.argv[1]).read().split("\n")[2].split()[6:9]]
for want in ([5.8590, -2.1106, -1.1391], [5.9064, -1.7891, -1.0204]):
    if all(abs(a - b) <= 1e-4 for a, b in zip(w, want)):
        sys.exit(1)
EOF
# Box-box contacts (docs/references.md §2 and the template's testCheckCollision):
# resting boxes, one step, the contact from --trace.
sat_case() {
    local name=$1 commands=$2
    shift 2
    printf "%b" "$commands" | "${cpp[@]}" --trace 2>&1 >/dev/null | grep '^contact' |
        sed -e 's/.*p = (\([^)]*\)), n = (\([^)]*\)), depth \([^,]*\),.*/\1 \2 \3/' -e 's/,//g' > "$tmp/sat.txt"
    expect_numbers "$name" "$tmp/sat.txt" 1 1e-6 "$@"
}
c45="0.92387953251128674 0 0 0.38268343236508978"
c90="0.70710678118654757 0 0 0.70710678118654746"
sat_case "SAT: unit cubes at 0 and (0.9, 0.2, 0.1): p, n, depth" \
    'add_body 0 0 0 1 1 1 1\nadd_body 0.9 0.2 0.1 1 1 1 1\nstep 1\n' 0.4 -0.3 -0.4 -1 0 0 0.1
sat_case "SAT: template case 1 (touching cubes)" \
    'add_body 1 1 1 1 1 1 1\nadd_body 2 2 2 1 1 1 1\nstep 1\n' 1.5 1.5 1.5 -1 0 0 0
sat_case "SAT: template case 2 (a corner of B)" \
    "add_body 0.2 5 1 9 2 3 1\nadd_body 0 0 0 5.6568543 5.6568543 2 1\nset_orientation 1 $c45\nstep 1\n" 0 4 1 0 1 0
sat_case "SAT: template case 3 (a corner of A)" \
    "add_body -2 0 1 2.829 2.829 2 1\nset_orientation 0 $c45\nadd_body 1 0.5 0 9 2 4 1\nset_orientation 1 $c90\nstep 1\n" \
    0.000405 0 0 -1 0 0

echo "== (b) Python against C++, correct and every mistake"
mistakes=$("${cpp[@]}" --help | sed -n '/^Mistake ids:/,/^$/p' | grep '^  ' | tr -d ' ')
py_mistakes=$("${py[@]}" --help | sed -n '/^Mistake ids:/,/^$/p' | grep '^  ' | tr -d ' ')
if [ "$mistakes" = "$py_mistakes" ] && [ "$(echo "$mistakes" | wc -l)" -eq 29 ]; then
    ok "both programs list the same 29 mistake ids"
else
    bad "the mistake id lists differ or are not 29 long"
fi
files=(motion-two-bodies collision-two-boxes collision-three-boxes template-public-test table-2-1)
for f in "${files[@]}"; do
    "${cpp[@]}" --restitution 0.7 < "$here/commands/$f.commands" > "$tmp/$f.correct"
done
compared=0
mismatched=0
for m in "" $mistakes; do
    args=(--restitution 0.7)
    [ -n "$m" ] && args+=(--mistake "$m")
    changed=no
    for f in "${files[@]}"; do
        "${cpp[@]}" "${args[@]}" < "$here/commands/$f.commands" > "$tmp/c.states"
        "${py[@]}" "${args[@]}" < "$here/commands/$f.commands" > "$tmp/p.states"
        compared=$((compared + 1))
        if ! "${compare[@]}" "$tmp/c.states" "$tmp/p.states" --rel 1e-9 > "$tmp/cmp.txt"; then
            mismatched=$((mismatched + 1))
            bad "Python vs C++ ${m:-correct} on $f:"
            sed 's/^/      /' "$tmp/cmp.txt" | tail -5
        fi
        cmp -s "$tmp/c.states" "$tmp/$f.correct" || changed=yes
    done
    if [ -n "$m" ] && [ "$changed" = no ]; then
        bad "--mistake $m changes no answer of the command files"
    fi
done
[ "$mismatched" -eq 0 ] && ok "Python = C++ to 1e-9 on $compared runs (5 files x (correct + 29 mistakes))"
# float against double: the float round-off is far below 1e-4 of the scale.
for f in motion-two-bodies collision-two-boxes; do
    "${cpp[@]}" --restitution 0.7 --float < "$here/commands/$f.commands" > "$tmp/f.states"
    if "${compare[@]}" "$tmp/$f.correct" "$tmp/f.states" --rel 1e-4 > "$tmp/cmp.txt"; then
        ok "--float = double to 1e-4 on $f ($(tail -1 "$tmp/cmp.txt" | sed 's/.*worst/worst/'))"
    else
        bad "--float vs double on $f"; tail -5 "$tmp/cmp.txt"
    fi
done

echo "== (c) the --fail modes"
scene='add_body 0 0 0 1 1 1 1\nstate 0\nstep 0.1\nstate 0\nstate 0\n'
for prog in cpp py; do
    if [ $prog = cpp ]; then run=("${cpp[@]}"); else run=("${py[@]}"); fi
    out=$(printf "$scene" | "${run[@]}" --fail nan 2>/dev/null)
    if [ "$(echo "$out" | sed -n 1p | grep -c nan)" = 0 ] && [ "$(echo "$out" | sed -n 2p | grep -c nan)" = 1 ]; then
        ok "$prog --fail nan: the second answer is nan"
    else bad "$prog --fail nan: $out"; fi
    out=$(printf "$scene" | "${run[@]}" --fail exit 2>/dev/null); status=$?
    if [ $status -eq 1 ] && [ "$(echo "$out" | wc -l)" = 1 ]; then
        ok "$prog --fail exit: status 1 after the first step"
    else bad "$prog --fail exit: status $status, output $out"; fi
    out=$(printf "$scene" | timeout 2 "${run[@]}" --fail hang 2>/dev/null); status=$?
    if [ $status -eq 124 ] && [ "$(echo "$out" | wc -l)" = 1 ]; then
        ok "$prog --fail hang: no answer after the first step (killed by timeout)"
    else bad "$prog --fail hang: status $status, output $out"; fi
    out=$(printf "$scene" | "${run[@]}" --fail garbage 2>/dev/null)
    if [ "$(echo "$out" | sort -u)" = hello ]; then ok "$prog --fail garbage: answers hello"; else bad "$prog --fail garbage: $out"; fi
done

echo "== (d) malformed input and bad options"
malformed() {
    local name=$1 input=$2 pattern=$3
    shift 3
    for prog in cpp py; do
        if [ $prog = cpp ]; then run=("${cpp[@]}"); else run=("${py[@]}"); fi
        printf "%b" "$input" | "${run[@]}" "$@" > "$tmp/out" 2> "$tmp/err"
        status=$?
        if [ $status -eq 2 ] && grep -q -- "$pattern" "$tmp/err" && [ ! -s "$tmp/out" ]; then
            ok "$prog $name: exit 2, \"$(head -c 110 "$tmp/err" | tr -d '\n')\""
        else
            bad "$prog $name: status $status, stderr: $(cat "$tmp/err")"
        fi
    done
}
malformed "unknown command" 'add_body 0 0 0 1 1 1 1\njump 3\n' "line 2: unknown command 'jump'"
malformed "too few numbers" 'add_body 0 0 0 1 1 1\n' "line 1: add_body needs 7 arguments"
malformed "not a number" 'add_body 0 0 0 1 1 1 1\nstep 0,1\n' "line 2: step: '0,1' is not a finite decimal number"
malformed "nan in the input" 'add_body 0 0 0 1 1 nan 1\n' "line 1: add_body: 'nan' is not a finite"
malformed "no such body" 'add_body 0 0 0 1 1 1 1\nstate 1\n' "line 2: state: there is no body 1"
malformed "fractional mass" 'add_body 0 0 0 1 1 1 2.5\n' "line 1: add_body: the mass '2.5' is not a whole number"
malformed "zero quaternion" 'add_body 0 0 0 1 1 1 1\nset_orientation 0 0 0 0 0\n' "line 2: set_orientation: the quaternion is zero"
malformed "unknown mistake id" '' "unknown mistake id 'typo'. Valid ids: velocity-before-position, " --mistake typo
malformed "hand-only mistake id" '' "'angle-in-degrees' is a hand-calculation mistake" --mistake angle-in-degrees
malformed "restitution out of range" '' "restitution needs a number from 0 to 1" --restitution 1.5

echo "== (e) tum_template_adapter.cpp against template_stub/"
for f in table-2-1 motion-two-bodies collision-two-boxes collision-three-boxes template-public-test; do
    "$tmp/adapter" < "$here/commands/$f.commands" > "$tmp/a.states" 2> "$tmp/a.err"
    "${cpp[@]}" < "$here/commands/$f.commands" > "$tmp/r.states"
    # The template's simulateTimestep(float) rounds h to float: 1e-6 relative.
    if "${compare[@]}" "$tmp/r.states" "$tmp/a.states" --rel 1e-6 > "$tmp/cmp.txt" && grep -q '^debug:' "$tmp/a.err"; then
        ok "adapter = reference on $f ($(tail -1 "$tmp/cmp.txt" | sed 's/.*worst/worst/')); the stub's prints went to stderr"
    else
        bad "adapter on $f"; tail -5 "$tmp/cmp.txt"
    fi
done
printf 'add_body 0 0 0 1 1 1 1\nstate 4\n' | "$tmp/adapter" > /dev/null 2> "$tmp/err"; status=$?
if [ $status -eq 2 ] && grep -q "line 2" "$tmp/err"; then ok "adapter: no such body: exit 2, $(cat "$tmp/err")"; else bad "adapter: no such body: status $status"; fi

echo
if [ "$failures" -eq 0 ]; then
    echo "selfcheck: all checks passed"
    exit 0
fi
echo "selfcheck: $failures check(s) FAILED"
exit 1
