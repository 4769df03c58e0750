#include "app/gui/shell/app_settings.h"

#include <QCryptographicHash>
#include <QMetaType>
#include <QSettings>
#include <QVariant>

#include <cstdio>

namespace rbw {

namespace {

const QString kLastLesson = QStringLiteral("lesson/last");
const QString kRecentFiles = QStringLiteral("files/recent");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");

// The seal: "RBWL", the layout version (4 bytes, big-endian), SHA-256 of the blob, blob.
const QByteArray kMagic = QByteArrayLiteral("RBWL");
constexpr qsizetype kHashSize = 32;
constexpr qsizetype kHeaderSize = 4 + 4 + kHashSize;

QByteArray versionBytes(int version)
{
    const quint32 v = static_cast<quint32>(version);
    QByteArray out(4, '\0');
    for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((v >> (8 * (3 - i))) & 0xffu);
    return out;
}

bool isType(const QVariant& v, QMetaType::Type type) { return v.metaType().id() == static_cast<int>(type); }

} // namespace

const QStringList& AppSettings::keys()
{
    static const QStringList all{kLastLesson, kRecentFiles, kGeometry, kState};
    return all;
}

void AppSettings::drop(const QString& key, const QString& reason)
{
    QSettings settings;
    std::fprintf(stderr, "rigid-workbook: settings: %s in %s dropped: %s\n", key.toLocal8Bit().constData(),
                 settings.fileName().toLocal8Bit().constData(), reason.toLocal8Bit().constData());
    settings.remove(key);
}

QString AppSettings::lastLesson()
{
    const QVariant v = QSettings().value(kLastLesson);
    if (!v.isValid()) return {};
    if (!isType(v, QMetaType::QString)) {
        drop(kLastLesson, QStringLiteral("not a lesson id (a %1)").arg(QString::fromLatin1(v.typeName())));
        return {};
    }
    return v.toString();
}

void AppSettings::setLastLesson(const QString& lessonId) { QSettings().setValue(kLastLesson, lessonId); }

QStringList AppSettings::recentFiles()
{
    const QVariant v = QSettings().value(kRecentFiles);
    if (!v.isValid()) return {};
    // A one-element list reads back as a string from the INI file.
    if (!isType(v, QMetaType::QStringList) && !isType(v, QMetaType::QString)) {
        drop(kRecentFiles, QStringLiteral("not a list of file names (a %1)").arg(QString::fromLatin1(v.typeName())));
        return {};
    }
    QStringList paths = v.toStringList();
    paths.removeAll(QString());
    return paths;
}

void AppSettings::setRecentFiles(const QStringList& paths)
{
    if (paths.isEmpty()) {
        QSettings().remove(kRecentFiles);
    } else {
        QSettings().setValue(kRecentFiles, paths);
    }
}

QByteArray AppSettings::seal(const QByteArray& blob)
{
    return kMagic + versionBytes(kLayoutVersion) + QCryptographicHash::hash(blob, QCryptographicHash::Sha256) + blob;
}

std::optional<QByteArray> AppSettings::unseal(const QByteArray& sealed, QString* reason)
{
    auto refuse = [&](const QString& why) -> std::optional<QByteArray> {
        if (reason != nullptr) *reason = why;
        return std::nullopt;
    };
    if (sealed.size() < kHeaderSize || !sealed.startsWith(kMagic)) {
        return refuse(QStringLiteral("not a layout saved by this app (an older version's, or damaged)"));
    }
    if (sealed.mid(4, 4) != versionBytes(kLayoutVersion)) {
        return refuse(QStringLiteral("a layout of another version of the window (this one is version %1)").arg(kLayoutVersion));
    }
    const QByteArray blob = sealed.mid(kHeaderSize);
    if (QCryptographicHash::hash(blob, QCryptographicHash::Sha256) != sealed.mid(8, kHashSize)) {
        return refuse(QStringLiteral("the layout is damaged (its checksum does not match)"));
    }
    return blob;
}

QByteArray AppSettings::sealedValue(const QString& key)
{
    const QVariant v = QSettings().value(key);
    if (!v.isValid()) return {};
    if (!isType(v, QMetaType::QByteArray)) {
        drop(key, QStringLiteral("not a saved layout (a %1)").arg(QString::fromLatin1(v.typeName())));
        return {};
    }
    QString reason;
    const std::optional<QByteArray> blob = AppSettings::unseal(v.toByteArray(), &reason);
    if (!blob) {
        drop(key, reason + QStringLiteral("; the window starts with the default layout"));
        return {};
    }
    return *blob;
}

QByteArray AppSettings::windowGeometry() { return sealedValue(kGeometry); }
QByteArray AppSettings::windowState() { return sealedValue(kState); }

void AppSettings::setWindowLayout(const QByteArray& geometry, const QByteArray& state)
{
    QSettings settings;
    settings.setValue(kGeometry, seal(geometry));
    settings.setValue(kState, seal(state));
}

void AppSettings::dropWindowLayout(const QString& reason)
{
    drop(kState, reason);
    QSettings().remove(kGeometry);
}

} // namespace rbw
