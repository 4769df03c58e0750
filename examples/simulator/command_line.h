// command_line.h: the reference simulator's options (--mistake, --restitution, --float,
// --trace, --fail, --help; README.md, "Flags of the reference simulator") and the one
// number syntax of its input: a plain finite decimal. A bad option ends the program
// with a message on stderr and exit status 2.
#pragma once

#include "mistakes.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace rbwref {

inline const char* const kProgram = "reference_simulator";

[[noreturn]] inline void die(const std::string& message)
{
    std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
    std::exit(2);
}

inline std::string validMistakeIds()
{
    std::string ids;
    for (const auto& d : kMistakeDefs) {
        if (std::strcmp(d.scope, "hand") == 0) continue;
        if (!ids.empty()) ids += ", ";
        ids += d.id;
    }
    return ids;
}

inline void printHelp()
{
    std::printf(
        "Usage: %s [--mistake ID]... [--restitution C] [--float] [--trace] [--fail MODE]\n"
        "A rigid-body simulator that speaks the workbook's simulator protocol on stdin/stdout\n"
        "(docs/simulator-protocol.md): the TUM explicit Euler step, the template's box-box\n"
        "test and the impulse, with no gravity and no damping.\n\n"
        "Options:\n"
        "  --mistake ID      switch on a mistake model (repeatable); see README.md\n"
        "  --restitution C   coefficient of restitution, 0 <= C <= 1 (default 0.5)\n"
        "  --float           compute in float, as the course template does\n"
        "  --trace           describe every contact on stderr\n"
        "  --fail MODE       misbehave on purpose, to test a driver: nan (the second state\n"
        "                    answer is nan), exit (exit status 1 after the first step),\n"
        "                    hang (no answers after the first step), garbage (answers hello)\n"
        "  --help            this text\n\n"
        "Mistake ids:\n",
        kProgram);
    for (const auto& d : kMistakeDefs) {
        if (std::strcmp(d.scope, "hand") != 0) std::printf("  %s\n", d.id);
    }
    std::printf("\nExit status: 0 after quit or end of input, 2 bad options or a malformed command.\n");
}

enum class Fail { None, Nan, Exit, Hang, Garbage };

struct Options {
    Mistakes mistakes;
    double restitution = 0.5;
    bool useFloat = false;
    bool trace = false;
    Fail fail = Fail::None;
};

// A plain decimal number: [+-] digits [. digits] [e [+-] digits] (or .digits), finite.
inline bool parseNumber(const std::string& token, double& value)
{
    size_t k = 0;
    const size_t n = token.size();
    if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
    size_t digits = 0;
    while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
    if (k < n && token[k] == '.') {
        ++k;
        while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
    }
    if (digits == 0) return false;
    if (k < n && (token[k] == 'e' || token[k] == 'E')) {
        ++k;
        if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
        size_t expDigits = 0;
        while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++expDigits;
        if (expDigits == 0) return false;
    }
    if (k != n) return false;
    errno = 0;
    value = std::strtod(token.c_str(), nullptr);
    return std::isfinite(value) && errno != ERANGE;
}

inline Options parseOptions(int argc, char** argv)
{
    Options o;
    bool failSeen = false;
    for (int k = 1; k < argc; ++k) {
        std::string arg = argv[k];
        std::string value;
        bool hasValue = false;
        const size_t eq = arg.find('=');
        if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
            hasValue = true;
        }
        const auto takeValue = [&]() {
            if (hasValue) return value;
            if (k + 1 >= argc) die(arg + " needs a value");
            return std::string(argv[++k]);
        };
        if (arg == "--help" || arg == "-h") {
            printHelp();
            std::exit(0);
        } else if (arg == "--mistake") {
            const std::string id = takeValue();
            if (!o.mistakes.enable(id)) {
                std::string why = "unknown mistake id '" + id + "'";
                for (const auto& d : kMistakeDefs) {
                    if (id == d.id) why = "'" + id + "' is a hand-calculation mistake; the protocol cannot show it";
                }
                die(why + ". Valid ids: " + validMistakeIds());
            }
        } else if (arg == "--restitution") {
            const std::string text = takeValue();
            if (!parseNumber(text, o.restitution) || o.restitution < 0 || o.restitution > 1) {
                die("--restitution needs a number from 0 to 1, got '" + text + "'");
            }
        } else if (arg == "--float" && !hasValue) {
            o.useFloat = true;
        } else if (arg == "--trace" && !hasValue) {
            o.trace = true;
        } else if (arg == "--fail") {
            const std::string mode = takeValue();
            if (failSeen) die("--fail given twice");
            failSeen = true;
            if (mode == "nan") o.fail = Fail::Nan;
            else if (mode == "exit") o.fail = Fail::Exit;
            else if (mode == "hang") o.fail = Fail::Hang;
            else if (mode == "garbage") o.fail = Fail::Garbage;
            else die("unknown --fail mode '" + mode + "' (valid: nan, exit, hang, garbage)");
        } else {
            die(std::string("unknown option '") + argv[k] + "' (try --help)");
        }
    }
    return o;
}

}   // namespace rbwref
