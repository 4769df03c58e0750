#include "app/gui/panels/editor/scene_editor.h"

#include "app/gui/panels/editor/scene_editor_model.h"

#include <QAction>
#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QStyledItemDelegate>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

namespace rbw {

namespace {

// A choice (integrator, convention, the body a force acts on) as a combo box of the
// values the model offers; free text otherwise.
class ChoiceDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        const QStringList options = index.data(SceneEditorModel::OptionsRole).toStringList();
        if (options.isEmpty()) return QStyledItemDelegate::createEditor(parent, option, index);
        auto* box = new QComboBox(parent);
        box->addItems(options);
        return box;
    }
    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        if (auto* box = qobject_cast<QComboBox*>(editor)) {
            const int i = box->findText(index.data(Qt::EditRole).toString());
            box->setCurrentIndex(std::max(0, i));
            return;
        }
        QStyledItemDelegate::setEditorData(editor, index);
    }
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
    {
        if (auto* box = qobject_cast<QComboBox*>(editor)) {
            model->setData(index, box->currentText(), Qt::EditRole);
            return;
        }
        QStyledItemDelegate::setModelData(editor, model, index);
    }
};

} // namespace

SceneEditor::SceneEditor(QWidget* parent)
    : QWidget(parent)
    , model_(new SceneEditorModel(this))
    , view_(new QTreeView)
    , toolBar_(new QToolBar)
    , state_(new QLabel)
{
    view_->setObjectName("sceneEditorView");
    view_->setModel(model_);
    view_->setItemDelegate(new ChoiceDelegate(view_));
    view_->setAlternatingRowColors(true);
    view_->setUniformRowHeights(true);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::SelectedClicked | QAbstractItemView::AnyKeyPressed);
    view_->header()->setStretchLastSection(true);
    view_->header()->setSectionResizeMode(SceneEditorModel::KeyColumn, QHeaderView::Interactive);
    view_->setColumnWidth(SceneEditorModel::KeyColumn, 190);

    toolBar_->setObjectName("sceneEditorToolBar");
    toolBar_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* add = toolBar_->addAction(tr("Add"));
    add->setObjectName("actionEditorAdd");
    add->setToolTip(tr("Add a body, force, torque, probe, plane or pair to the selected group"));
    connect(add, &QAction::triggered, this, &SceneEditor::addToSelectedGroup);
    auto* remove = toolBar_->addAction(tr("Remove"));
    remove->setObjectName("actionEditorRemove");
    remove->setToolTip(tr("Remove the selected body, force, torque, probe, plane or pair"));
    connect(remove, &QAction::triggered, this, &SceneEditor::removeSelected);
    toolBar_->addSeparator();

    state_->setObjectName("sceneEditorState");
    state_->setWordWrap(true);
    state_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    state_->setMargin(4);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(toolBar_);
    layout->addWidget(view_, 1);
    layout->addWidget(state_);

    connect(model_, &SceneEditorModel::sceneEdited, this, &SceneEditor::onEdited);
    connect(model_, &SceneEditorModel::editRefused, this, [this](const QString& text) {
        state_->setStyleSheet(QStringLiteral("QLabel{color:#b3261e}"));
        state_->setText(tr("Not changed: %1").arg(text));
        emit message(text);
    });
}

void SceneEditor::setScene(const SceneDef& scene, const QString& filePath)
{
    model_->setScene(scene);
    filePath_ = filePath;
    issues_.clear();
    setModified(false);
    state_->setStyleSheet(QString());
    state_->setText(tr("Double-click a value to edit it. A valid edit restarts the scene from t = 0."));
    expandDefault();
}

const SceneDef& SceneEditor::scene() const { return model_->scene(); }

void SceneEditor::setModified(bool modified)
{
    if (modified_ == modified) return;
    modified_ = modified;
    emit modifiedChanged(modified);
}

void SceneEditor::expandDefault()
{
    // The settings and the bodies open; a scene of many bodies keeps them folded.
    view_->expand(model_->index(SceneEditorModel::Settings, 0));
    const QModelIndex bodies = model_->index(SceneEditorModel::Bodies, 0);
    view_->expand(bodies);
    if (model_->rowCount(bodies) <= 3) {
        for (int r = 0; r < model_->rowCount(bodies); ++r) view_->expand(model_->index(r, 0, bodies));
    }
    view_->resizeColumnToContents(SceneEditorModel::KeyColumn);
}

void SceneEditor::onEdited()
{
    setModified(true);
    issues_.clear();
    QHash<QString, QString> marks;
    for (const SceneIssue& issue : validate(model_->scene())) {
        const QString path = QString::fromStdString(issue.path);
        issues_ << QStringLiteral("%1: %2").arg(path, QString::fromStdString(issue.reason));
        marks.insert(path, QString::fromStdString(issue.reason));
    }
    model_->setIssues(marks);
    if (issues_.isEmpty()) {
        state_->setStyleSheet(QString());
        state_->setText(tr("Applied: the scene runs with these numbers from t = 0."));
        emit applyRequested(model_->scene());
    } else {
        state_->setStyleSheet(QStringLiteral("QLabel{color:#b3261e}"));
        const QString count = issues_.size() == 1 ? tr("1 problem") : tr("%1 problems").arg(issues_.size());
        state_->setText(tr("Not applied; the running scene is unchanged (%1):\n").arg(count) + issues_.mid(0, 8).join('\n'));
        emit message(issues_.first());
    }
}

void SceneEditor::addToSelectedGroup()
{
    const QModelIndex current = view_->currentIndex();
    SceneEditorModel::Group group = SceneEditorModel::groupOf(current);
    if (group == SceneEditorModel::Settings || group == SceneEditorModel::GroupCount) group = SceneEditorModel::Bodies;
    const QModelIndex added = model_->addElement(group);
    expandDefault();
    if (added.isValid()) {
        view_->expand(added.parent());
        view_->expand(added);
        view_->setCurrentIndex(added);
        view_->scrollTo(added);
    }
}

void SceneEditor::removeSelected()
{
    const QModelIndex current = view_->currentIndex();
    if (SceneEditorModel::elementOf(current) < 0 || SceneEditorModel::groupOf(current) == SceneEditorModel::Settings) {
        emit message(tr("Select a body, force, torque, probe, plane or pair to remove"));
        return;
    }
    QModelIndex element = current;
    while (element.parent().isValid() && element.parent().parent().isValid()) element = element.parent();
    model_->removeElement(element);
    expandDefault();
}

} // namespace rbw
