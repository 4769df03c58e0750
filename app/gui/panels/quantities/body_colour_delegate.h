// The quantities table's body swatches: a group row named after a body (the table
// groups each stage's rows by body) gets a square in that body's colour, the one
// colour the 3D view and the plots use for it (app/gui/style/body_colours.h). A delegate,
// so the table's model (TraceModel) stays as it is.
#pragma once

#include <QList>
#include <QStringList>
#include <QStyledItemDelegate>

namespace rbw {

class BodyColourDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit BodyColourDelegate(QObject* parent = nullptr);

    // The scene's bodies, in scene order (the colour is the body's index's).
    void setBodies(const QStringList& names, const QList<bool>& fixed);
    // The body a row of the table is the group of, or -1.
    int bodyOfRow(const QModelIndex& index) const;

protected:
    void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override;

private:
    QStringList names_;
    QList<bool> fixed_;
};

} // namespace rbw
