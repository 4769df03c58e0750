#include "app/core/lesson_catalogue.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
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
        lessons.append(Lesson{id, o.value("name").toString(id), o.value("description").toString(),
                              scenePath, dir.filePath(id + "/lesson.md")});
    }
    return lessons;
}

} // namespace rbw
