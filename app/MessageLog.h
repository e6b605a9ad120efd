#pragma once

#include <QDateTime>
#include <QJsonArray>
#include <QObject>
#include <QString>
#include <QVector>

#include <functional>

class QLabel;
class QWidget;

namespace prisca::app {

enum class MessageLevel { Info, Warning, Error };

/// One line of the message log: when, from where (a panel, or a worker's logging category),
/// how serious, and what.
struct LogEntry {
    QDateTime time;
    QString source;
    MessageLevel level = MessageLevel::Info;
    QString text;
    int repeats = 1;  ///< the same message from the same source in a row is one line, counted
};

/// The window's message log: every status, warning and error the panels show, and the info,
/// warnings and errors the workers write under the `prisca.*` logging categories. One per
/// window, a child of it: a panel, dialog or label finds its window's log by walking up the
/// object tree (MessageLog::of), so two windows keep two logs and a panel built outside any
/// window logs nowhere. Posting from any thread is safe (a worker's message is queued to the
/// window's thread). Kept to the last kCapacity lines.
class MessageLog : public QObject {
    Q_OBJECT
  public:
    static constexpr int kCapacity = 5000;
    /// Lines kept with a session file (the newest).
    static constexpr int kSavedLines = 1000;

    explicit MessageLog(QObject* parent = nullptr);
    ~MessageLog() override;

    /// The log of the window `context` is in: the first MessageLog that is a direct child of
    /// `context` or of one of its ancestors; null when there is none (a panel in a test without
    /// a window, a page not yet placed). Call on the object's thread.
    static MessageLog* of(const QObject* context);
    /// Adds a line; from another thread, queued to this object's thread.
    void post(const QString& source, MessageLevel level, const QString& text);

    const QVector<LogEntry>& entries() const { return entries_; }
    void clear();

    /// The line's text with its repeat count, "(x3)", when it came more than once.
    static QString shownText(const LogEntry& entry);
    /// "HH:mm:ss.zzz  level  source  text" per line, tab-separated.
    static QString format(const LogEntry& entry);
    static QString levelName(MessageLevel level);
    /// The newest kSavedLines as JSON (time ISO 8601 with ms, source, level, text, repeats).
    QJsonArray toJson() const;
    /// Lines read back from toJson()'s form; malformed ones are skipped. Appended in order.
    int append(const QJsonArray& saved);

    /// Routes messages of the `prisca.*` logging categories (info and above) into this log, then
    /// on to the handler that was installed before (stderr), until this log is destroyed or
    /// another takes them. Qt's message handler is one per process and carries no context, so
    /// this is the one place the log is reached without being handed: the window that owns it
    /// calls this once.
    void captureQtMessages();

  signals:
    /// A line was added (index in entries()), or the last line's repeat count grew.
    void added(int index);
    void repeated(int index);
    void cleared();
    /// The oldest lines were dropped to stay within kCapacity.
    void trimmed(int count);

  private:
    void add(LogEntry entry);

    QVector<LogEntry> entries_;
};

/// Posts to the log of the window `context` is in (MessageLog::of), if any.
void logMessage(const QObject* context, const QString& source, MessageLevel level,
                const QString& text);
/// Shows `text` on a panel's status label and logs it in the label's window's log.
void showStatus(QLabel* label, const QString& source, const QString& text,
                MessageLevel level = MessageLevel::Info);
/// The same for a message that follows the interface language: `text` is called now and again
/// on every language change for as long as the label still shows what it gave (a message set
/// since, by any means, is left alone). The log keeps the line as first shown.
void showStatus(QLabel* label, const QString& source, std::function<QString()> text,
                MessageLevel level = MessageLevel::Info);
/// `text` on a label now and again on every language change while the label still shows it,
/// without logging it (a progress line that changes every few seconds).
void setTranslatedText(QLabel* label, std::function<QString()> text);
/// A warning box, logged as a warning with the box's title as its source.
void warningBox(QWidget* parent, const QString& title, const QString& text);

}  // namespace prisca::app
