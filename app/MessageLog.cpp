#include "app/MessageLog.h"

#include "app/widgets/ModalDialog.h"

#include <QCoreApplication>
#include <QEvent>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QThread>

#include <mutex>

namespace prisca::app {

namespace {

// The log that receives the prisca.* categories (Qt's handler is a plain function, one per
// process). Guarded against a worker posting while the window closes; recursive because a line
// added on the window's thread may make a slot log again (a warning from a slot). A standard
// mutex, which ThreadSanitizer sees (QRecursiveMutex locks inside Qt's uninstrumented library).
std::recursive_mutex capturingMutex;
MessageLog* capturingLog = nullptr;
QtMessageHandler previousHandler = nullptr;

void handleQtMessage(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    const QLatin1String category(context.category ? context.category : "");
    if (type != QtDebugMsg && category.startsWith(QLatin1String("prisca."))) {
        const MessageLevel level = type == QtInfoMsg      ? MessageLevel::Info
                                   : type == QtWarningMsg ? MessageLevel::Warning
                                                          : MessageLevel::Error;
        const std::lock_guard<std::recursive_mutex> lock(capturingMutex);
        if (capturingLog) {
            capturingLog->post(QString(category.mid(7)), level, message);
        }
    }
    if (previousHandler) {
        previousHandler(type, context, message);
    }
}

}  // namespace

MessageLog::MessageLog(QObject* parent) : QObject(parent) {
    setObjectName(QStringLiteral("messageLog"));
}

MessageLog::~MessageLog() {
    const std::lock_guard<std::recursive_mutex> lock(capturingMutex);
    if (capturingLog == this) {
        capturingLog = nullptr;
    }
}

MessageLog* MessageLog::of(const QObject* context) {
    for (const QObject* node = context; node; node = node->parent()) {
        if (auto* log = node->findChild<MessageLog*>(QString(), Qt::FindDirectChildrenOnly)) {
            return log;
        }
    }
    return nullptr;
}

void MessageLog::post(const QString& source, MessageLevel level, const QString& text) {
    LogEntry entry{QDateTime::currentDateTime(), source, level, text.trimmed(), 1};
    if (entry.text.isEmpty()) {
        return;
    }
    if (QThread::currentThread() == thread()) {
        add(std::move(entry));
    } else {
        QMetaObject::invokeMethod(
            this, [this, entry]() mutable { add(std::move(entry)); }, Qt::QueuedConnection);
    }
}

void MessageLog::add(LogEntry entry) {
    if (!entries_.isEmpty()) {
        LogEntry& last = entries_.last();
        if (last.source == entry.source && last.level == entry.level && last.text == entry.text) {
            ++last.repeats;
            last.time = entry.time;
            emit repeated(static_cast<int>(entries_.size()) - 1);
            return;
        }
    }
    if (entries_.size() >= kCapacity) {
        const int drop = static_cast<int>(entries_.size()) - kCapacity + 1;
        entries_.remove(0, drop);
        emit trimmed(drop);
    }
    entries_.append(std::move(entry));
    emit added(static_cast<int>(entries_.size()) - 1);
}

void MessageLog::clear() {
    entries_.clear();
    emit cleared();
}

QString MessageLog::levelName(MessageLevel level) {
    switch (level) {
        case MessageLevel::Info:
            return tr("info");
        case MessageLevel::Warning:
            return tr("warning");
        case MessageLevel::Error:
            return tr("error");
    }
    return QString();
}

QString MessageLog::shownText(const LogEntry& entry) {
    return entry.repeats > 1 ? entry.text + QStringLiteral(" (x%1)").arg(entry.repeats)
                             : entry.text;
}

QString MessageLog::format(const LogEntry& entry) {
    return QStringLiteral("%1\t%2\t%3\t%4")
        .arg(entry.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")), levelName(entry.level),
             entry.source, shownText(entry));
}

namespace {
const char* levelKey(MessageLevel level) {
    switch (level) {
        case MessageLevel::Warning:
            return "warning";
        case MessageLevel::Error:
            return "error";
        case MessageLevel::Info:
            break;
    }
    return "info";
}
}  // namespace

QJsonArray MessageLog::toJson() const {
    QJsonArray lines;
    const qsizetype first = std::max<qsizetype>(0, entries_.size() - kSavedLines);
    for (qsizetype i = first; i < entries_.size(); ++i) {
        const LogEntry& e = entries_[i];
        QJsonObject line{{"time", e.time.toString(Qt::ISODateWithMs)},
                         {"source", e.source},
                         {"level", QLatin1String(levelKey(e.level))},
                         {"text", e.text}};
        if (e.repeats > 1) {
            line.insert("repeats", e.repeats);
        }
        lines.append(line);
    }
    return lines;
}

int MessageLog::append(const QJsonArray& saved) {
    int read = 0;
    for (const QJsonValue& value : saved) {
        const QJsonObject line = value.toObject();
        const QDateTime time =
            QDateTime::fromString(line.value("time").toString(), Qt::ISODateWithMs);
        const QString text = line.value("text").toString();
        if (!time.isValid() || text.isEmpty()) {
            continue;
        }
        const QString level = line.value("level").toString();
        LogEntry entry{time, line.value("source").toString(),
                       level == QLatin1String("error")     ? MessageLevel::Error
                       : level == QLatin1String("warning") ? MessageLevel::Warning
                                                           : MessageLevel::Info,
                       text, std::clamp(line.value("repeats").toInt(1), 1, 1 << 30)};
        if (entries_.size() >= kCapacity) {
            entries_.removeFirst();
            emit trimmed(1);
        }
        entries_.append(std::move(entry));  // not merged: a saved log is kept line for line
        emit added(static_cast<int>(entries_.size()) - 1);
        ++read;
    }
    return read;
}

void MessageLog::captureQtMessages() {
    static const bool installed = [] {
        previousHandler = qInstallMessageHandler(handleQtMessage);
        return true;
    }();
    Q_UNUSED(installed);
    const std::lock_guard<std::recursive_mutex> lock(capturingMutex);
    capturingLog = this;
}

void logMessage(const QObject* context, const QString& source, MessageLevel level,
                const QString& text) {
    if (MessageLog* log = MessageLog::of(context)) {
        log->post(source, level, text);
    }
}

namespace {

// Re-sets its label's text in the new language on a language change, while the label still
// shows the text it set last.
class LabelTranslator : public QObject {
  public:
    LabelTranslator(QLabel* label, std::function<QString()> text)
        : QObject(label), label_(label), text_(std::move(text)) {
        setObjectName(QStringLiteral("labelTranslator"));
        shown_ = text_();
        label_->setText(shown_);
        label_->installEventFilter(this);
    }
    const QString& shown() const { return shown_; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == label_ && event->type() == QEvent::LanguageChange &&
            label_->text() == shown_) {
            shown_ = text_();
            label_->setText(shown_);
        }
        return false;
    }

  private:
    QLabel* label_;
    std::function<QString()> text_;
    QString shown_;
};

void dropTranslator(QLabel* label) {
    for (auto* old : label->findChildren<LabelTranslator*>(QString(), Qt::FindDirectChildrenOnly)) {
        delete old;
    }
}

}  // namespace

void showStatus(QLabel* label, const QString& source, const QString& text, MessageLevel level) {
    dropTranslator(label);
    label->setText(text);
    logMessage(label, source, level, text);
}

void showStatus(QLabel* label, const QString& source, std::function<QString()> text,
                MessageLevel level) {
    dropTranslator(label);
    auto* translator = new LabelTranslator(label, std::move(text));
    logMessage(label, source, level, translator->shown());
}

void setTranslatedText(QLabel* label, std::function<QString()> text) {
    dropTranslator(label);
    new LabelTranslator(label, std::move(text));
}

void warningBox(QWidget* parent, const QString& title, const QString& text) {
    logMessage(parent, title, MessageLevel::Warning, text);
    ModalDialog::warning(parent, title, text);
}

}  // namespace prisca::app
