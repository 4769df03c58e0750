#!/usr/bin/env bash
# tst_install: `cmake --install` lays out the Debian-style tree (packaging/CMakeLists.txt),
# the installed programs work from it with nothing pointing at the source tree (the
# lessons are found relative to the executable, also after the tree is moved), the
# desktop file, the AppStream metadata and the man pages pass their checkers when those
# are installed, and `cpack -G DEB` builds a package holding the same tree with the
# run-time dependencies, whose own programs run.
#
# Usage: tst_install.sh CMAKE CPACK SOURCE_DIR BUILD_DIR APP_ID VERSION
# (tests/CMakeLists.txt passes these). Exit status 0 when every check passes.
set -uo pipefail

cmake=$1 cpack=$2 source_dir=$3 build=$4 app_id=$5 version=$6

# Prove the relative lookup: nothing may point the programs at the source tree.
unset RBW_LESSONS_DIR RBW_SOURCE_ROOT

tmp=$(mktemp -d "${TMPDIR:-/tmp}/rbw-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "PASS: $*"; }
skip() { echo "SKIP: $*"; }

# ---------------------------------------------------------------------------------
# 1. cmake --install into <tmp>/stage/usr

prefix=$tmp/stage/usr
if ! "$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1; then
    cat "$tmp/install.log"
    echo "FAIL: cmake --install $build --prefix $prefix"
    exit 1
fi
pass "cmake --install --prefix $prefix"

data=share/rigid-body-workbook
expected_files=(
    bin/rbw
    bin/rigid-workbook
    "$data/lessons/01-one-step/scene.json"
    "$data/lessons/01-one-step/lesson.md"
    "$data/lessons/01-one-step/derivation.md"
    "$data/lessons/07-bounce/impulses.json"
    "$data/source/physics/engine/world.cpp"
    "$data/source/physics/engine/integrators/explicit_euler.cpp"
    "share/applications/$app_id.desktop"
    "share/icons/hicolor/scalable/apps/$app_id.svg"
    "share/metainfo/$app_id.metainfo.xml"
    share/man/man1/rbw.1.gz
    share/man/man1/rigid-workbook.1.gz
)
for f in "${expected_files[@]}"; do
    [ -f "$prefix/$f" ] || fail "installed tree lacks $f"
done
for f in bin/rbw bin/rigid-workbook; do
    [ -x "$prefix/$f" ] || fail "$f is not executable"
done

# Every lesson file and every physics source, nothing else beside the programs.
(cd "$source_dir/lessons" && find . -type f \( -name '*.json' -o -name '*.md' \) | sort) >"$tmp/lessons.src"
(cd "$prefix/$data/lessons" && find . -type f | sort) >"$tmp/lessons.inst"
diff -u "$tmp/lessons.src" "$tmp/lessons.inst" >/dev/null || fail "installed lessons differ from lessons/: $(diff "$tmp/lessons.src" "$tmp/lessons.inst" | head -5)"
(cd "$source_dir/physics" && find . -type f \( -name '*.h' -o -name '*.cpp' \) | sort) >"$tmp/physics.src"
(cd "$prefix/$data/source/physics" && find . -type f | sort) >"$tmp/physics.inst"
diff -u "$tmp/physics.src" "$tmp/physics.inst" >/dev/null || fail "installed physics sources differ from physics/"
cmp -s "$source_dir/physics/engine/world.cpp" "$prefix/$data/source/physics/engine/world.cpp" || fail "installed world.cpp is not the source's"
bin_listing=$(cd "$prefix/bin" && ls | tr '\n' ' ')
[ "$bin_listing" = "rbw rigid-workbook " ] || fail "bin/ holds \"$bin_listing\", expected rbw and rigid-workbook only"
top_listing=$(cd "$prefix" && ls | tr '\n' ' ')
[ "$top_listing" = "bin share " ] || fail "the prefix holds \"$top_listing\", expected bin and share only"
[ "$failures" -eq 0 ] && pass "installed tree: $(cd "$prefix" && find . -type f | wc -l) files, lessons and physics sources complete"

# ---------------------------------------------------------------------------------
# 2. The installed programs, with no environment pointing at the source tree

# rbw lessons prints each scene's path relative to the current directory: from $tmp,
# the installed lessons are stage/usr/share/..., the source tree's would be elsewhere.
check_lessons() {   # check_lessons BIN_DIR EXPECTED_PREFIX LABEL
    local out
    if ! out=$(cd "$tmp" && "$1/rbw" lessons 2>&1); then
        fail "$3: rbw lessons failed: $out"
        return
    fi
    local want=$(find "$source_dir/lessons" -mindepth 1 -maxdepth 1 -type d | wc -l)
    local ids=$(printf '%s\n' "$out" | grep -cE '^[0-9]{2}-[a-z0-9-]+  ')
    [ "$ids" -eq "$want" ] || fail "$3: rbw lessons lists $ids lessons, lessons/ has $want"
    printf '%s\n' "$out" | grep -q '^01-one-step  ' || fail "$3: rbw lessons does not list 01-one-step"
    local paths=$(printf '%s\n' "$out" | grep -E '^    .*\.json$' | sed 's/^    //')
    local outside=$(printf '%s\n' "$paths" | grep -cv "^$2/share/rigid-body-workbook/lessons/")
    [ "$outside" -eq 0 ] || fail "$3: rbw lessons reads lessons outside the installed tree: $(printf '%s\n' "$paths" | head -2)"
    [ "$failures" -eq "$before" ] && pass "$3: rbw lessons lists the $want installed lessons ($2/share/rigid-body-workbook/lessons)"
}
before=$failures
check_lessons "$prefix/bin" stage/usr "installed"

out=$("$prefix/bin/rbw" --version 2>&1)
[ "$out" = "rbw $version" ] && pass "rbw --version: $out" || fail "rbw --version printed \"$out\", expected \"rbw $version\""

out=$(cd "$tmp" && "$prefix/bin/rbw" run stage/usr/$data/lessons/01-one-step/scene.json 2>&1)
printf '%s' "$out" | grep -q '4.918032786885245' && pass "installed rbw runs lesson 1 (omega_y = 4.918032786885245)" \
    || fail "installed rbw run of lesson 1: $(printf '%s' "$out" | head -3)"

# No display: --version and --help must not need one.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$prefix/bin/rigid-workbook" --version 2>&1)
rc=$?
[ $rc -eq 0 ] && [ "$out" = "rigid-workbook $version" ] && pass "rigid-workbook --version without a display: $out" \
    || fail "rigid-workbook --version (exit $rc) printed \"$out\", expected \"rigid-workbook $version\""
out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$prefix/bin/rigid-workbook" --help 2>&1)
rc=$?
[ $rc -eq 0 ] && printf '%s' "$out" | grep -q -- '--lesson' && printf '%s' "$out" | grep -q '^Usage: rigid-workbook' \
    && pass "rigid-workbook --help without a display" || fail "rigid-workbook --help (exit $rc): $out"

# The tree is relocatable: moved elsewhere, the programs still find their lessons.
mv "$tmp/stage" "$tmp/moved"
before=$failures
check_lessons "$tmp/moved/usr/bin" moved/usr "moved tree"
mv "$tmp/moved" "$tmp/stage"

# ---------------------------------------------------------------------------------
# 3. Desktop file, AppStream metadata, man pages

desktop=$prefix/share/applications/$app_id.desktop
if command -v desktop-file-validate >/dev/null; then
    out=$(desktop-file-validate "$desktop" 2>&1)
    rc=$?
    if [ $rc -eq 0 ] && ! printf '%s' "$out" | grep -qiE 'error|warning'; then
        pass "desktop-file-validate $app_id.desktop${out:+ (hints: $out)}"
    else
        fail "desktop-file-validate (exit $rc): $out"
    fi
else
    skip "desktop-file-validate not installed (Debian package desktop-file-utils)"
fi
grep -q "^Icon=$app_id$" "$desktop" || fail "the desktop file's Icon is not $app_id"
grep -q '^Exec=rigid-workbook$' "$desktop" || fail "the desktop file does not run rigid-workbook"

if command -v appstreamcli >/dev/null; then
    out=$(appstreamcli validate --no-net "$prefix/share/metainfo/$app_id.metainfo.xml" 2>&1)
    rc=$?
    [ $rc -eq 0 ] && pass "appstreamcli validate --no-net: $(printf '%s' "$out" | tail -1)" || fail "appstreamcli validate (exit $rc): $out"
    # The whole tree: the metainfo's launchable desktop file and its icon are found.
    out=$(appstreamcli validate-tree --no-net "$tmp/stage" 2>&1)
    rc=$?
    [ $rc -eq 0 ] && pass "appstreamcli validate-tree --no-net: $(printf '%s' "$out" | tail -1)" || fail "appstreamcli validate-tree (exit $rc): $out"
else
    skip "appstreamcli not installed (Debian package appstream)"
fi

if command -v groff >/dev/null; then
    for page in rbw.1 rigid-workbook.1; do
        out=$(gzip -dc "$prefix/share/man/man1/$page.gz" | LC_ALL=C.UTF-8 groff -man -Tutf8 -ww -z 2>&1)
        [ -z "$out" ] && pass "groff -man -ww: $page has no warnings" || fail "groff warnings in $page: $out"
    done
    gzip -dc "$prefix/share/man/man1/rbw.1.gz" | grep -q "Rigid Body Workbook $version" || fail "rbw.1 does not name version $version"
else
    skip "groff not installed: man pages not checked"
fi

# ---------------------------------------------------------------------------------
# 4. cpack -G DEB, then the package's contents and control fields

if ! command -v dpkg-deb >/dev/null; then
    skip "dpkg-deb not installed: the .deb is not checked"
else
    if ! "$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/cpack" >"$tmp/cpack.log" 2>&1; then
        cat "$tmp/cpack.log"
        fail "cpack -G DEB"
    fi
    deb=$(ls "$tmp"/cpack/*.deb 2>/dev/null | head -1)
    if [ -z "$deb" ]; then
        fail "cpack made no .deb"
    else
        pass "cpack -G DEB: $(basename "$deb")"
        dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' >"$tmp/deb.list"
        for f in "${expected_files[@]}"; do
            grep -qx "/usr/$f" "$tmp/deb.list" || fail "the .deb lacks /usr/$f"
        done
        n_deb=$(dpkg-deb -c "$deb" | grep -c '^-')
        n_tree=$(cd "$prefix" && find . -type f | wc -l)
        [ "$n_deb" -eq "$n_tree" ] || fail "the .deb holds $n_deb files, the installed tree $n_tree"
        [ "$(dpkg-deb -f "$deb" Package)" = rigid-body-workbook ] || fail "Package is $(dpkg-deb -f "$deb" Package)"
        [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version is $(dpkg-deb -f "$deb" Version)"
        [ "$(dpkg-deb -f "$deb" Section)" = education ] || fail "Section is $(dpkg-deb -f "$deb" Section)"
        [ -n "$(dpkg-deb -f "$deb" Maintainer)" ] || fail "no Maintainer"
        [ -n "$(dpkg-deb -f "$deb" Homepage)" ] && fail "a Homepage field, but the project has none"
        depends=$(dpkg-deb -f "$deb" Depends)
        for dep in libjs-katex fonts-katex libqt6webenginecore6-bin libqt6webenginewidgets6 libqt6charts6 \
                   libqt6openglwidgets6 libqt6widgets6 libqt6core6 libc6 libstdc++6; do
            printf '%s\n' "$depends" | tr ',' '\n' | sed 's/^ *//; s/ .*//' | grep -qx "$dep" \
                || fail "Depends lacks $dep: $depends"
        done
        [ "$failures" -eq 0 ] && pass "the .deb holds the installed tree ($n_deb files); Depends: $depends"

        # The packaged (stripped) programs run from the unpacked package.
        dpkg-deb -x "$deb" "$tmp/unpacked"
        out=$("$tmp/unpacked/usr/bin/rbw" --version 2>&1)
        [ "$out" = "rbw $version" ] || fail "the packaged rbw --version printed \"$out\""
        before=$failures
        check_lessons "$tmp/unpacked/usr/bin" unpacked/usr "unpacked .deb"
    fi
fi

echo
if [ "$failures" -ne 0 ]; then
    echo "tst_install: $failures check(s) failed"
    exit 1
fi
echo "tst_install: all checks passed"
