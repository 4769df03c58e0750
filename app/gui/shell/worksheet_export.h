// A lesson's worksheet and answer key for one seed (docs/exercises.md), written as
// HTML (exerciseWorksheetHtml, the same page `rbw exercise --worksheet` writes) or as
// PDF (that page laid out by QTextDocument on A4 through QPdfWriter). Each file is
// replaced atomically (QSaveFile): complete or not at all.
#pragma once

#include <QByteArray>
#include <QString>

namespace rbw {

struct ExerciseSpec;
struct GeneratedExercise;

// The PDF of an HTML page (simple HTML: headings, paragraphs, tables), A4 portrait.
QByteArray htmlToPdf(const QString& html, const QString& title);

struct WorksheetFiles {
    QString worksheet;   // the path written for the worksheet
    QString answerKey;   // and for the answer key: "<name>-key.<ext>" beside it
};

// Writes the worksheet to `path` (.pdf: PDF, anything else: HTML) and the answer key
// beside it. False with *error naming the file and the reason if either cannot be
// written.
bool exportWorksheet(const ExerciseSpec& spec, const GeneratedExercise& g, const QString& path,
                     WorksheetFiles* written, QString* error);

} // namespace rbw
