#pragma once

#include <QWidget>

class QComboBox;
class QPushButton;
class QTableWidget;

namespace prisca::app {

class MessageLog;
struct LogEntry;

/// The message log as a table (time, level, source, message), newest at the bottom and
/// followed while the operator is at the bottom; warnings and errors coloured. Shows all lines
/// or only warnings and errors; Copy (Ctrl+C) copies the selected lines, or all, as tab-separated
/// text; Clear empties the log.
class MessageLogPanel : public QWidget {
    Q_OBJECT
  public:
    explicit MessageLogPanel(MessageLog& log, QWidget* parent = nullptr);

    /// The lines shown now, as Copy would put them on the clipboard.
    QString selectedOrAllText() const;
    QTableWidget* table() const { return table_; }

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void rebuild();
    void addRow(int index);
    void updateRow(int row, const LogEntry& entry);
    bool shown(const LogEntry& entry) const;
    void copy();

    MessageLog& log_;
    QComboBox* filter_;
    QPushButton* copy_;
    QPushButton* clear_;
    QTableWidget* table_;
    QVector<int> rowEntry_;  ///< the log entry each table row shows
};

}  // namespace prisca::app
