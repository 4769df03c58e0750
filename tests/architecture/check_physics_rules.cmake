# Two rules of docs/architecture.md that a reviewer would otherwise have to check by
# hand, for every .h and .cpp under DIR (the repository's physics/):
#   1. no file over 450 lines (issue 9: one concept per file, each readable in one go);
#   2. physics is Qt-free: no #include of a Qt header (<Q...> or <Qt...>).
# Usage: cmake -DDIR=<dir> -P check_physics_rules.cmake
# Fails (FATAL_ERROR) with every offending file named. tests/CMakeLists.txt also runs it
# on a directory that breaks both rules, which must fail (the negative control).
cmake_policy(VERSION 3.25)
if(NOT DEFINED DIR OR NOT IS_DIRECTORY "${DIR}")
    message(FATAL_ERROR "check_physics_rules: -DDIR=<directory> is required")
endif()
set(kMaxLines 450)
file(GLOB_RECURSE files "${DIR}/*.h" "${DIR}/*.cpp")
list(LENGTH files count)
if(count EQUAL 0)
    message(FATAL_ERROR "check_physics_rules: no .h or .cpp file under ${DIR}")
endif()
set(problems "")
foreach(f IN LISTS files)
    # Lines as wc -l counts them: newline characters (a list of source lines would
    # split at every ';').
    file(READ "${f}" content)
    string(REGEX MATCHALL "\n" newlines "${content}")
    list(LENGTH newlines n)
    if(n GREATER kMaxLines)
        string(APPEND problems "\n  ${f}: ${n} lines (at most ${kMaxLines})")
    endif()
    file(STRINGS "${f}" qt REGEX "^[ \t]*#[ \t]*include[ \t]*<Q")
    if(qt)
        string(APPEND problems "\n  ${f}: includes Qt (${qt}); physics is Qt-free")
    endif()
endforeach()
if(problems)
    message(FATAL_ERROR "physics rules broken:${problems}")
endif()
message(STATUS "${count} files under ${DIR}: none over ${kMaxLines} lines, none includes Qt")
