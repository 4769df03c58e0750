// What a student has typed into "Check my numbers", kept per lesson and step, so that
// switching lessons or steps keeps the entries and coming back shows them again. The
// texts are kept as typed (a half-written entry survives too); a row is named by its
// key (CheckModel::rowKey: quantity, body, contact, index).
#pragma once

#include <QHash>
#include <QString>

namespace rbw {

class AnswersStore {
public:
    QString text(const QString& lesson, long step, const QString& rowKey) const;
    // An empty (or blank) text removes the entry.
    void setText(const QString& lesson, long step, const QString& rowKey, const QString& text);
    // How many entries that step has.
    int count(const QString& lesson, long step) const;
    void clearStep(const QString& lesson, long step);

private:
    static QString stepKey(const QString& lesson, long step);
    QHash<QString, QHash<QString, QString>> texts_;   // "lesson#step" -> row key -> text
};

} // namespace rbw
