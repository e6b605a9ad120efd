#include "app/widgets/ChannelMapEditor.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>

namespace prisca::app {

namespace {
const QString kSettingsKey = QStringLiteral("rig/channels");
}

ChannelMapEditor::ChannelMapEditor(QWidget* parent)
    : QWidget(parent), table_(new QTableWidget(this)), problem_(new QLabel(this)) {
    table_->setObjectName(QStringLiteral("channelMap"));
    table_->setColumnCount(5);
    table_->setRowCount(2);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->setMaximumHeight(90);
    problem_->setObjectName(QStringLiteral("channelProblem"));
    problem_->setStyleSheet(QStringLiteral("color: #b00020"));
    problem_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(table_);
    layout->addWidget(problem_);

    // The map as the operator left it: "channel:trim:min:max:reversed" per control; a saved
    // control that would make the map invalid is ignored.
    const QStringList saved = QSettings().value(kSettingsKey).toStringList();
    for (int i = 0; i < saved.size() && i < static_cast<int>(channels_.controls.size()); ++i) {
        const QStringList f = saved[i].split(QLatin1Char(':'));
        if (f.size() == 5) {
            devices::ChannelMap trial = channels_;
            trial.controls[i] = {f[0].toInt(), f[1].toDouble(), f[2].toDouble(), f[3].toDouble(),
                                 f[4] == QLatin1String("1")};
            if (trial.validate().isEmpty()) {
                channels_ = trial;
            }
        }
    }
    connect(table_, &QTableWidget::itemChanged, this, &ChannelMapEditor::apply);
    show();
    retranslateUi();
}

void ChannelMapEditor::setControlNames(const QStringList& names) {
    table_->setVerticalHeaderLabels({names.value(0), names.value(1)});
}

void ChannelMapEditor::show() {
    updating_ = true;
    for (int row = 0; row < 2 && row < static_cast<int>(channels_.controls.size()); ++row) {
        const devices::ChannelSetting& s = channels_.controls[row];
        const QStringList cells = {QString::number(s.channel + 1), QString::number(s.trim),
                                   QString::number(s.minimum), QString::number(s.maximum)};
        for (int col = 0; col < 4; ++col) {
            table_->setItem(row, col, new QTableWidgetItem(cells[col]));
        }
        auto* reversed = new QTableWidgetItem;
        reversed->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
        reversed->setCheckState(s.reversed ? Qt::Checked : Qt::Unchecked);
        table_->setItem(row, 4, reversed);
    }
    updating_ = false;
}

void ChannelMapEditor::apply() {
    if (updating_) {
        return;
    }
    devices::ChannelMap edited = channels_;
    QString problem;
    for (int row = 0; row < 2 && row < static_cast<int>(edited.controls.size()); ++row) {
        double values[4] = {};
        for (int col = 0; col < 4; ++col) {
            bool ok = false;
            const QTableWidgetItem* item = table_->item(row, col);
            values[col] = item ? item->text().toDouble(&ok) : 0.0;
            if (!ok) {
                problem = tr("'%1' is not a number").arg(item ? item->text() : QString());
            }
        }
        devices::ChannelSetting& s = edited.controls[row];
        s.channel = static_cast<int>(values[0]) - 1;
        s.trim = values[1];
        s.minimum = values[2];
        s.maximum = values[3];
        s.reversed = table_->item(row, 4) && table_->item(row, 4)->checkState() == Qt::Checked;
    }
    if (problem.isEmpty()) {
        problem = edited.validate();
    }
    problem_->setText(problem);
    if (!problem.isEmpty()) {
        return;  // nothing half-applied
    }
    channels_ = edited;
    QStringList saved;
    for (const devices::ChannelSetting& s : channels_.controls) {
        saved << QStringLiteral("%1:%2:%3:%4:%5")
                     .arg(s.channel)
                     .arg(s.trim)
                     .arg(s.minimum)
                     .arg(s.maximum)
                     .arg(s.reversed ? 1 : 0);
    }
    QSettings().setValue(kSettingsKey, saved);
    emit channelsChanged(channels_);
}

void ChannelMapEditor::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void ChannelMapEditor::retranslateUi() {
    table_->setHorizontalHeaderLabels(
        {tr("CH"), tr("trim [µs]"), tr("min [µs]"), tr("max [µs]"), tr("reversed")});
    table_->setToolTip(
        tr("Which transmitter channel each control drives, its trim, its "
           "travel limits and its direction"));
}

}  // namespace prisca::app
