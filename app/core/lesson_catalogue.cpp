#include "app/core/lesson_catalogue.h"

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
        const QDir exe(QCoreApplication::applicationDirPath());
        for (const QString& rel : {QStringLiteral("lessons"), QStringLiteral("../lessons"),
                                   QStringLiteral("../share/rigid-workbook/lessons")}) {
            if (QFile::exists(exe.filePath(rel + "/01-one-step/scene.json"))) {
                return QDir::cleanPath(exe.filePath(rel));
            }
        }
    }
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
        const QJsonObject o = QJsonDocument::fromJson(file.readAll()).object();
        const QString textPath = dir.filePath(id + "/lesson.md");
        lessons.append(Lesson{id, o.value("name").toString(id), o.value("description").toString(), scenePath,
                              textPath, false});
        // Variants: the folder's other scene files, e.g. 07-bounce/impulses.json.
        const QDir folder(dir.filePath(id));
        for (const QString& variant : folder.entryList({"*.json"}, QDir::Files, QDir::Name)) {
            if (variant == QLatin1String("scene.json")) {
                continue;
            }
            QFile v(folder.filePath(variant));
            if (!v.open(QIODevice::ReadOnly)) {
                continue;
            }
            const QString variantId = id + '/' + QFileInfo(variant).completeBaseName();
            const QJsonObject vo = QJsonDocument::fromJson(v.readAll()).object();
            lessons.append(Lesson{variantId, vo.value("name").toString(variantId), vo.value("description").toString(),
                                  folder.filePath(variant), textPath, true});
        }
    }
    return lessons;
}

} // namespace rbw
