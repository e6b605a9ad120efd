#include "app/rig/RigDoctorPage.h"

#include "app/MessageLog.h"
#include "app/widgets/NamedWidget.h"

#include <algorithm>

#include <QDeadlineTimer>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QThread>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace prisca::app {

RigDoctorPage::RigDoctorPage(QWidget* parent)
    : QWidget(parent),
      check_(named<QPushButton>(this, "checkComputer")),
      summary_(named<QLabel>(this, "computerSummary")),
      lines_(named<QTreeWidget>(this, "computerReport")) {
    setObjectName(QStringLiteral("rigDoctorPage"));
    summary_->setWordWrap(true);
    lines_->setColumnCount(3);
    lines_->setRootIsDecorated(false);
    lines_->setWordWrap(true);
    lines_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    lines_->header()->setStretchLastSection(true);
    lines_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    lines_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(check_);
    top->addWidget(summary_, 1);
    layout->addLayout(top);
    layout->addWidget(lines_, 1);
    connect(check_, &QPushButton::clicked, this, &RigDoctorPage::check);
    retranslateUi();
}

RigDoctorPage::~RigDoctorPage() {
    if (!thread_) {
        return;
    }
    // A query of the system ends by itself within a second; a wedged driver must not hold the
    // window's closing: the thread then ends on its own (it holds nothing of this page) and is
    // deleted when it does.
    if (thread_->wait(QDeadlineTimer(2000))) {
        delete thread_;
    } else {
        disconnect(thread_, nullptr, this, nullptr);
        connect(thread_, &QThread::finished, thread_, &QObject::deleteLater);
    }
}

void RigDoctorPage::check() {
    if (thread_) {
        return;
    }
    // What the window is set to use is checked even when the system does not list it.
    const QSettings settings;
    request_ = rig::DoctorRequest();
    if (const QString port = settings.value(QStringLiteral("rig/port")).toString();
        !port.isEmpty()) {
        request_.ports << port;
    }
    const QString camera = settings.value(QStringLiteral("rig/path")).toString();
    if (settings.value(QStringLiteral("rig/source"), 0).toInt() != 0 &&
        camera.startsWith(QLatin1String("/dev/"))) {
        request_.cameras << camera;
    }
    auto facts = std::make_shared<rig::HostFacts>();
    const rig::DoctorRequest request = request_;
    thread_ = QThread::create([facts, request] { *facts = rig::gatherFacts(request); });
    thread_->setObjectName(QStringLiteral("prisca-doctor"));
    connect(thread_, &QThread::finished, this, [this, facts] {
        facts_ = facts;
        finish();
    });
    check_->setEnabled(false);
    setTranslatedText(summary_, [] { return tr("Checking this computer..."); });
    thread_->start();
}

void RigDoctorPage::finish() {
    thread_->wait();
    delete thread_;
    thread_ = nullptr;
    check_->setEnabled(true);
    showReport();
    const long missing =
        std::count_if(report_->items.begin(), report_->items.end(),
                      [](const rig::DoctorItem& i) { return !i.ok && i.required; });
    showStatus(
        summary_, tr("This computer"),
        [missing] {
            return missing == 0 ? tr("The rig has what it needs on this computer.")
                                : tr("%n line(s) to fix before the rig can run.", "", int(missing));
        },
        missing == 0 ? MessageLevel::Info : MessageLevel::Warning);
    emit checked();
}

void RigDoctorPage::showReport() {
    if (!facts_) {
        return;
    }
    report_ = rig::diagnose(request_, *facts_);  // its sentences in the language of now
    lines_->clear();
    for (const rig::DoctorItem& i : report_->items) {
        const QString mark = i.ok ? tr("OK") : i.required ? tr("Fix") : tr("Note");
        auto* line = new QTreeWidgetItem(lines_, {mark, i.label, i.detail});
        line->setData(0, Qt::UserRole, i.key);
        line->setToolTip(2, i.detail);
        if (!i.ok) {
            line->setForeground(0,
                                i.required ? QColor(0xb0, 0x20, 0x20) : QColor(0x90, 0x60, 0x00));
        }
    }
}

void RigDoctorPage::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (!shownOnce_) {
        shownOnce_ = true;
        check();
    }
}

void RigDoctorPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
        showReport();
    }
    QWidget::changeEvent(event);
}

void RigDoctorPage::retranslateUi() {
    check_->setText(tr("Check this computer"));
    check_->setToolTip(
        tr("The serial ports and whether you may open them, the cameras, the "
           "display and the free space: what prisca-cli doctor checks"));
    lines_->setHeaderLabels({QString(), tr("What"), tr("Found, or what to do")});
    if (!report_ && !thread_) {
        summary_->setText(tr("Not checked yet."));
    }
}

}  // namespace prisca::app
