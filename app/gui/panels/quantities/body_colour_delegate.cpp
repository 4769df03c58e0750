#include "app/gui/panels/quantities/body_colour_delegate.h"

#include "app/gui/style/body_colours.h"

#include <QPainter>
#include <QPixmap>

#include <algorithm>

namespace rbw {

BodyColourDelegate::BodyColourDelegate(QObject* parent)
    : QStyledItemDelegate(parent)
{
}

void BodyColourDelegate::setBodies(const QStringList& names, const QList<bool>& fixed)
{
    names_ = names;
    fixed_ = fixed;
}

int BodyColourDelegate::bodyOfRow(const QModelIndex& index) const
{
    // A body's group row: a row with children whose text is the body's name.
    if (!index.isValid() || index.column() != 0 || !index.model()->hasChildren(index)) return -1;
    return static_cast<int>(names_.indexOf(index.data(Qt::DisplayRole).toString()));
}

void BodyColourDelegate::initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    const int body = bodyOfRow(index);
    if (body < 0) return;
    const int side = std::max(8, option->fontMetrics.height() - 4);
    QPixmap swatch(side, side);
    swatch.fill(Qt::transparent);
    {
        QPainter p(&swatch);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QColor(0, 0, 0, 90));
        p.setBrush(bodyQColor(body, body < fixed_.size() && fixed_[body], names_.value(body)));
        p.drawRoundedRect(QRectF(0.5, 0.5, side - 1, side - 1), 2, 2);
    }
    option->features |= QStyleOptionViewItem::HasDecoration;
    option->icon = QIcon(swatch);
    option->decorationSize = QSize(side, side);
}

} // namespace rbw
