#include "app/exercise/answers_store.h"

namespace rbw {

QString AnswersStore::stepKey(const QString& lesson, long step)
{
    return lesson + QLatin1Char('#') + QString::number(step);
}

QString AnswersStore::text(const QString& lesson, long step, const QString& rowKey) const
{
    const auto it = texts_.constFind(stepKey(lesson, step));
    return it == texts_.constEnd() ? QString() : it->value(rowKey);
}

void AnswersStore::setText(const QString& lesson, long step, const QString& rowKey, const QString& text)
{
    const QString key = stepKey(lesson, step);
    if (text.trimmed().isEmpty()) {
        auto it = texts_.find(key);
        if (it != texts_.end()) {
            it->remove(rowKey);
            if (it->isEmpty()) texts_.erase(it);
        }
        return;
    }
    texts_[key].insert(rowKey, text);
}

int AnswersStore::count(const QString& lesson, long step) const
{
    const auto it = texts_.constFind(stepKey(lesson, step));
    return it == texts_.constEnd() ? 0 : static_cast<int>(it->size());
}

void AnswersStore::clearStep(const QString& lesson, long step)
{
    texts_.remove(stepKey(lesson, step));
}

} // namespace rbw
