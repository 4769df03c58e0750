// rbw exercise LESSON --seed N [--output FILE] [--worksheet FILE.html]
//              [--answer-key FILE.html] [--answers-key FILE.json]
// New numbers for practice (docs/exercises.md): the lesson's scene with the values its
// exercise.json varies drawn for seed N, written to standard output or FILE; optionally
// the HTML worksheet, its answer key and the key as an answers file for rbw check.
// Every file is written by app/output/atomic_file.h; two outputs naming one file, or
// an output naming one of the lesson's files, are refused before anything is written. Exit status: 0 success, 2 bad input (the
// message names the file, the JSON path and the reason).
#pragma once

#include <QCommandLineParser>
#include <QString>

namespace rbw {

int runExerciseCommand(const QCommandLineParser& parser, const QString& lesson);

} // namespace rbw
