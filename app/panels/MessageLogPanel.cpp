#include "app/panels/MessageLogPanel.h"

#include "app/MessageLog.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace prisca::app {

namespace {
enum Column { TimeColumn, LevelColumn, SourceColumn, TextColumn, ColumnCount };
}

MessageLogPanel::MessageLogPanel(MessageLog& log, QWidget* parent)
    : QWidget(parent),
      log_(log),
      filter_(new QComboBox(this)),
      copy_(new QPushButton(this)),
      clear_(new QPushButton(this)),
      table_(new QTableWidget(0, ColumnCount, this)) {
    setObjectName(QStringLiteral("messageLogPanel"));
    filter_->setObjectName(QStringLiteral("messageFilter"));
    filter_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    copy_->setObjectName(QStringLiteral("copyMessages"));
    clear_->setObjectName(QStringLiteral("clearMessages"));
    table_->setObjectName(QStringLiteral("messageTable"));
    table_->verticalHeader()->setVisible(false);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->horizontalHeader()->setSectionResizeMode(TimeColumn, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(LevelColumn, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(SourceColumn, QHeaderView::ResizeToContents);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setTabKeyNavigation(false);  // Tab moves on to the next control, not cell by cell
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setWordWrap(false);
    table_->setTextElideMode(Qt::ElideRight);
    auto* copyAction = new QAction(table_);
    copyAction->setShortcut(QKeySequence::Copy);
    copyAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    table_->addAction(copyAction);
    connect(copyAction, &QAction::triggered, this, &MessageLogPanel::copy);

    auto* bar = new QHBoxLayout;
    bar->addWidget(filter_);
    bar->addStretch(1);
    bar->addWidget(copy_);
    bar->addWidget(clear_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(table_, 1);

    connect(filter_, &QComboBox::currentIndexChanged, this, &MessageLogPanel::rebuild);
    connect(copy_, &QPushButton::clicked, this, &MessageLogPanel::copy);
    connect(clear_, &QPushButton::clicked, &log_, &MessageLog::clear);
    connect(&log_, &MessageLog::added, this, &MessageLogPanel::addRow);
    connect(&log_, &MessageLog::repeated, this, [this](int index) {
        const int row = static_cast<int>(rowEntry_.lastIndexOf(index));
        if (row >= 0) {
            updateRow(row, log_.entries()[index]);
        }
    });
    connect(&log_, &MessageLog::cleared, this, &MessageLogPanel::rebuild);
    connect(&log_, &MessageLog::trimmed, this, [this](int count) {
        // The oldest lines left the log: their rows go, the others' indices shift.
        int gone = 0;
        while (gone < rowEntry_.size() && rowEntry_[gone] < count) {
            ++gone;
        }
        rowEntry_.remove(0, gone);
        for (int& entry : rowEntry_) {
            entry -= count;
        }
        for (int i = 0; i < gone; ++i) {
            table_->removeRow(0);
        }
    });
    retranslateUi();
    rebuild();
}

bool MessageLogPanel::shown(const LogEntry& entry) const {
    return filter_->currentIndex() <= 0 || entry.level != MessageLevel::Info;
}

void MessageLogPanel::rebuild() {
    table_->setRowCount(0);
    rowEntry_.clear();
    for (int i = 0; i < log_.entries().size(); ++i) {
        addRow(i);
    }
}

void MessageLogPanel::addRow(int index) {
    const LogEntry& entry = log_.entries()[index];
    if (!shown(entry)) {
        return;
    }
    QScrollBar* scroll = table_->verticalScrollBar();
    const bool following = scroll->value() >= scroll->maximum() - 2;
    const int row = table_->rowCount();
    table_->insertRow(row);
    rowEntry_.append(index);
    updateRow(row, entry);
    if (following) {
        table_->scrollToBottom();
    }
}

void MessageLogPanel::updateRow(int row, const LogEntry& entry) {
    const QStringList cells = {entry.time.toString(QStringLiteral("HH:mm:ss")),
                               MessageLog::levelName(entry.level), entry.source,
                               MessageLog::shownText(entry)};
    const QColor colour = entry.level == MessageLevel::Error     ? QColor(0xb0, 0x00, 0x20)
                          : entry.level == MessageLevel::Warning ? QColor(0x9a, 0x56, 0x00)
                                                                 : QColor();
    for (int c = 0; c < ColumnCount; ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        if (colour.isValid()) {
            item->setForeground(colour);
        }
        if (c == TextColumn) {
            item->setToolTip(entry.text);  // the whole line where the column is too narrow
        }
        table_->setItem(row, c, item);
    }
}

QString MessageLogPanel::selectedOrAllText() const {
    QList<int> rows;
    for (const QModelIndex& index : table_->selectionModel()->selectedRows()) {
        rows.append(index.row());
    }
    if (rows.isEmpty()) {
        for (int r = 0; r < table_->rowCount(); ++r) {
            rows.append(r);
        }
    }
    std::sort(rows.begin(), rows.end());
    QStringList lines;
    for (int row : rows) {
        if (row < rowEntry_.size() && rowEntry_[row] < log_.entries().size()) {
            lines.append(MessageLog::format(log_.entries()[rowEntry_[row]]));
        }
    }
    return lines.join(QLatin1Char('\n'));
}

void MessageLogPanel::copy() {
    QApplication::clipboard()->setText(selectedOrAllText());
}

void MessageLogPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void MessageLogPanel::retranslateUi() {
    const int filter = std::max(0, filter_->currentIndex());
    const QSignalBlocker blocker(filter_);
    filter_->clear();
    filter_->addItem(tr("All messages"));
    filter_->addItem(tr("Warnings and errors"));
    filter_->setCurrentIndex(filter);
    copy_->setText(tr("Copy"));
    copy_->setToolTip(tr("Copy the selected lines, or all shown, as tab-separated text (Ctrl+C)"));
    clear_->setText(tr("Clear"));
    table_->setHorizontalHeaderLabels({tr("Time"), tr("Level"), tr("Source"), tr("Message")});
    rebuild();  // the level names
}

}  // namespace prisca::app
