// Helpers for the derivation tests: run a lesson to a step, and read the LaTeX of the
// derivation rows back out of a page.
#pragma once

#include "app/scene/scene_loader.h"
#include "physics/engine/world.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

#include <QtTest>

namespace rbw::test {

inline QString lessonDir(const QString& id)
{
    return QStringLiteral(RBW_SOURCE_DIR "/lessons/") + id;
}

inline SceneDef lessonScene(const QString& id)
{
    const SceneLoadResult r = loadSceneFile(lessonDir(id) + QStringLiteral("/scene.json"));
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

// Every scene of every lesson folder that has a derivation template: the lesson's own
// scene.json and its variants (the folder's other scene files, which share the
// template), as "folder/file.json".
inline QStringList lessonScenesWithTemplates()
{
    QStringList out;
    const QDir dir(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
    for (const QString& d : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        if (!QFileInfo::exists(dir.filePath(d + QStringLiteral("/derivation.md")))) continue;
        const QDir lesson(dir.filePath(d));
        for (const QString& f : lesson.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            if (f != QLatin1String("exercise.json")) out << d + '/' + f;
        }
    }
    return out;
}

// The trace of step k (steps 0..k are taken).
inline StepTrace traceOfStep(const SceneDef& scene, int k)
{
    World w(scene);
    StepTrace t;
    for (int i = 0; i <= k; ++i) {
        if (!w.step(&t).ok) qFatal("step %d failed", i);
    }
    return t;
}

// The LaTeX of every math element of a page (display and inline), unescaped; for a
// row, its stacked form.
inline QStringList mathOf(const QString& html)
{
    static const QRegularExpression re(QStringLiteral(R"(<(?:div|span) class="tex(?: display)?"(?: data-inline="[^"]*")?>(.*?)</(?:div|span)>)"));
    QStringList out;
    QRegularExpressionMatchIterator it = re.globalMatch(html);
    while (it.hasNext()) {
        QString t = it.next().captured(1);
        t.replace(QLatin1String("&lt;"), QLatin1String("<"));
        t.replace(QLatin1String("&gt;"), QLatin1String(">"));
        t.replace(QLatin1String("&quot;"), QLatin1String("\""));
        t.replace(QLatin1String("&amp;"), QLatin1String("&"));
        out << t;
    }
    return out;
}

// Index of the first display row whose LaTeX starts with `\begin{aligned} <start>`; -1 if none.
inline int rowIndex(const QStringList& math, const QString& start, int from = 0)
{
    const QString prefix = QStringLiteral("\\begin{aligned} ") + start;
    for (int i = from; i < math.size(); ++i) {
        if (math[i].startsWith(prefix)) return i;
    }
    return -1;
}

inline QString vec(const QString& a, const QString& b, const QString& c)
{
    return QStringLiteral("\\begin{pmatrix} %1 \\\\ %2 \\\\ %3 \\end{pmatrix}").arg(a, b, c);
}

inline QString mat(const QStringList& rows)
{
    return QStringLiteral("\\begin{pmatrix} ") + rows.join(QStringLiteral(" \\\\ ")) + QStringLiteral(" \\end{pmatrix}");
}

} // namespace rbw::test
