#include "app/core/lesson_catalogue.h"

#include "app/core/source_root.h"
#include "app/scene/scene_format.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

namespace rbw {

QString lessonsDirectory()
{
    const QString fromEnv = qEnvironmentVariable("RBW_LESSONS_DIR");
    if (!fromEnv.isEmpty()) {
        return fromEnv;
    }
    if (QCoreApplication::instance() != nullptr) {
        // Beside or above the executable (an unpacked folder), then the installed
        // package's data folder (usr/bin/rbw -> usr/share/rigid-body-workbook/lessons).
        const QDir exe(QCoreApplication::applicationDirPath());
        const QStringList candidates{exe.filePath(QStringLiteral("lessons")), exe.filePath(QStringLiteral("../lessons")),
                                     installedDataDirectory() + QStringLiteral("/lessons")};
        for (const QString& dir : candidates) {
            if (QFile::exists(dir + QStringLiteral("/01-one-step/scene.json"))) {
                return QDir::cleanPath(dir);
            }
        }
    }
    // The source tree the program was built from (a build tree).
    return QStringLiteral(RBW_SOURCE_LESSONS_DIR);
}

QList<Lesson> lessonCatalogue(const QString& directory)
{
    QList<Lesson> lessons;
    const QDir dir(directory);
    for (const QString& id : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QString scenePath = dir.filePath(id + "/scene.json");
        QFile file(scenePath);
        if (!file.open(QIODevice::ReadOnly)) {
            continue;
        }
        // The scene's own name and description (the scene-format table's keys).
        const QString nameKey = sceneformat::key(sceneformat::Key::Name);
        const QString descriptionKey = sceneformat::key(sceneformat::Key::Description);
        const QJsonObject o = QJsonDocument::fromJson(file.readAll()).object();
        const QString textPath = dir.filePath(id + "/lesson.md");
        lessons.append(Lesson{id, o.value(nameKey).toString(id), o.value(descriptionKey).toString(), scenePath,
                              textPath, false});
        // Variants: the folder's other scene files, e.g. 07-bounce/impulses.json.
        const QDir folder(dir.filePath(id));
        for (const QString& variant : folder.entryList({"*.json"}, QDir::Files, QDir::Name)) {
            // exercise.json describes new numbers for the lesson (docs/exercises.md), not a scene
            if (variant == QLatin1String("scene.json") || variant == QLatin1String("exercise.json")) {
                continue;
            }
            QFile v(folder.filePath(variant));
            if (!v.open(QIODevice::ReadOnly)) {
                continue;
            }
            const QString variantId = id + '/' + QFileInfo(variant).completeBaseName();
            const QJsonObject vo = QJsonDocument::fromJson(v.readAll()).object();
            // Its own text NAME.md beside NAME.json, else the lesson's.
            const QString ownText = folder.filePath(QFileInfo(variant).completeBaseName() + QStringLiteral(".md"));
            lessons.append(Lesson{variantId, vo.value(nameKey).toString(variantId), vo.value(descriptionKey).toString(),
                                  folder.filePath(variant), QFile::exists(ownText) ? ownText : textPath, true});
        }
    }
    return lessons;
}

LessonArgument resolveLessonArgument(const QString& argument, const QList<Lesson>& lessons)
{
    LessonArgument result;
    for (const Lesson& l : lessons) {
        if (l.id == argument) {
            result.lessonId = l.id;
            return result;
        }
    }
    const QFileInfo info(argument);
    const bool looksLikePath = argument.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) ||
                               argument.contains('/') || argument.contains('\\') || info.exists();
    if (!looksLikePath) {
        QStringList ids;
        for (const Lesson& l : lessons) {
            if (!l.variant) ids << l.id;
        }
        result.error = QStringLiteral("unknown lesson \"%1\"; give a lesson id (%2) or the path of a scene file")
                           .arg(argument, ids.join(QStringLiteral(", ")));
        return result;
    }
    if (!info.isFile()) {
        result.error = QStringLiteral("%1: cannot open: %2").arg(argument, info.exists() ? QStringLiteral("not a file")
                                                                                         : QStringLiteral("no such file"));
        return result;
    }
    for (const Lesson& l : lessons) {
        if (QFileInfo(l.scenePath).canonicalFilePath() == info.canonicalFilePath()) {
            result.lessonId = l.id;
            return result;
        }
    }
    result.file = info.absoluteFilePath();
    return result;
}

} // namespace rbw
