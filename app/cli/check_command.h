// rbw check SCENE ANSWERS.json [ANSWERS2.json ...] [--step K] [--tolerance REL]
//           [--format text|json|csv]
// Checks a student's numbers for step K of a scene (physics/workbook/checker/checker.h) and
// prints one result per answer: the verdict (correct, wrong, follows-from-earlier), the
// workbook's number, the student's, the mistakes a wrong one shows and an explanation.
// Several answer files give one CSV row per file and answer: a marking sheet.
// Exit status: 0 every answer correct, 1 any not, 2 bad input, 3 the scene blew up
// before step K.
#pragma once

#include <QCommandLineParser>
#include <QStringList>

namespace rbw {

int runCheckCommand(const QCommandLineParser& parser, const QString& scenePath, const QStringList& answerPaths);

} // namespace rbw
