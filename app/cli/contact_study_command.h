// rbw contact-study PROBLEM [--iterations 1,2,4,8,16] [--dt H1,H2,...] [--t-end T]
//                   [--boxes N] [--output FILE]
// The speed/accuracy trade of contacts (physics/workbook/lab/contact_study.h): PROBLEM
// (resting-box, tower or rain) in the course model and in the manifold model at each
// solver iteration count, at each h, as CSV (app/output/study_csv.h). Progress goes to
// stderr. Exit status: 0 done, 2 bad input (the message names the option and the reason).
#pragma once

#include <QCommandLineParser>
#include <QString>

namespace rbw {

int runContactStudyCommand(const QCommandLineParser& parser, const QString& problem);

} // namespace rbw
