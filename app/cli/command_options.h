// Each rbw command accepts only its own options, each single-value option once
// (issue 22): `rbw run S --step 5` (a typo of --steps, an option of check) used to run
// the scene's own steps without a word; `--seed 5 --seed 6` silently took the last.
#pragma once

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

namespace rbw::cli {

// The long names of the options `command` accepts (without "--"); empty for a command
// that takes none, or one not in the table.
QStringList commandOptions(const QString& command);

// Empty when every option on the command line belongs to `command` and none is
// repeated; else the message, e.g. "run: --step is not an option of run; did you
// mean --steps?".
QString optionProblem(const QCommandLineParser& parser, const QString& command);

} // namespace rbw::cli
