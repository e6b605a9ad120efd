#include "app/widgets/BundleChooser.h"

#include "app/widgets/ModalDialog.h"
#include "core/FileIo.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace prisca::app {

namespace {
constexpr qint64 kMaxHeaderBytes = 16 << 20;  // as TrialBundle::load reads it
constexpr int kFolderRole = Qt::UserRole;
}  // namespace

std::vector<BundleEntry> BundleChooser::scan(const QStringList& parents) {
    std::vector<BundleEntry> entries;
    QStringList seen;
    for (const QString& parent : parents) {
        const QDir dir(parent);
        if (parent.isEmpty() || !dir.exists()) {
            continue;
        }
        for (const QFileInfo& folder : dir.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            const QString path = folder.absoluteFilePath();
            if (seen.contains(path)) {
                continue;
            }
            seen << path;
            core::FileError error;
            const auto json = core::readFileBounded(
                QDir(path).filePath(QStringLiteral("bundle.json")), kMaxHeaderBytes, &error);
            if (!json) {
                continue;  // not a bundle
            }
            const QJsonObject header = QJsonDocument::fromJson(*json).object();
            if (header.isEmpty()) {
                continue;
            }
            BundleEntry e;
            e.folder = path;
            e.rig = header.value("kind").toString() == QLatin1String("rig");
            e.when = QDateTime::fromString(header.value("started").toString(), Qt::ISODate);
            if (!e.when.isValid()) {
                e.when = folder.birthTime().isValid() ? folder.birthTime() : folder.lastModified();
            }
            e.method = header.value("method").toString();
            e.trial = header.value("trial").toInt();
            e.complete = header.contains("result");
            const QJsonObject result = header.value("result").toObject();
            if (!e.complete) {
                e.outcome = tr("incomplete");
            } else if (result.value("failsafe").toBool()) {
                e.outcome = tr("failsafe: %1").arg(result.value("reason").toString());
            } else if (result.contains("finalPositionErrorCm")) {
                e.outcome = tr("parked %1 cm")
                                .arg(result.value("finalPositionErrorCm").toDouble(), 0, 'f', 1);
            } else if (result.value("stopped").toBool()) {
                e.outcome = tr("stopped");
            }
            entries.push_back(e);
        }
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const BundleEntry& a, const BundleEntry& b) { return a.when > b.when; });
    return entries;
}

BundleChooser::BundleChooser(const QStringList& parents, QWidget* parent)
    : QDialog(parent), list_(new QTreeWidget(this)) {
    setObjectName(QStringLiteral("bundleChooser"));
    setWindowTitle(tr("Replay a trial bundle"));
    list_->setObjectName(QStringLiteral("bundleList"));
    list_->setColumnCount(4);
    list_->setHeaderLabels({tr("Started"), tr("Method"), tr("Trial"), tr("Outcome")});
    list_->setRootIsDecorated(true);
    list_->setUniformRowHeights(true);
    list_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    list_->header()->setStretchLastSection(true);
    auto* rig = new QTreeWidgetItem(list_);
    auto* simulated = new QTreeWidgetItem(list_);
    int rigCount = 0, simulatedCount = 0;
    for (const BundleEntry& e : scan(parents)) {
        auto* item = new QTreeWidgetItem(e.rig ? rig : simulated);
        item->setText(0, e.when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
        item->setText(1, e.method);
        item->setText(2, e.trial > 0 ? QString::number(e.trial) : QString());
        item->setText(3, e.outcome);
        item->setToolTip(0, QDir::toNativeSeparators(e.folder));
        item->setData(0, kFolderRole, e.folder);
        ++(e.rig ? rigCount : simulatedCount);
    }
    rig->setText(0, tr("Trials on the rig (%1)").arg(rigCount));
    simulated->setText(0, tr("Simulated trials (%1)").arg(simulatedCount));
    for (QTreeWidgetItem* group : {rig, simulated}) {
        group->setFirstColumnSpanned(true);
        group->setFlags(Qt::ItemIsEnabled);
        QFont bold = group->font(0);
        bold.setBold(true);
        group->setFont(0, bold);
    }
    rig->setExpanded(true);
    simulated->setExpanded(rigCount == 0 || simulatedCount <= 10);
    // The newest of the rig's, else the newest simulated one.
    if (QTreeWidgetItem* newest = rig->childCount() > 0         ? rig->child(0)
                                  : simulated->childCount() > 0 ? simulated->child(0)
                                                                : nullptr) {
        list_->setCurrentItem(newest);
    }
    auto* empty = new QLabel(
        tr("No trial bundles yet in %1.").arg(QDir::toNativeSeparators(parents.value(0))), this);
    empty->setVisible(rigCount + simulatedCount == 0);
    empty->setWordWrap(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, this);
    auto* other = buttons->addButton(tr("Other folder..."), QDialogButtonBox::ActionRole);
    other->setObjectName(QStringLiteral("otherBundleFolder"));
    connect(buttons, &QDialogButtonBox::accepted, this, [this] { choose(list_->currentItem()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(list_, &QTreeWidget::itemActivated, this,
            [this](QTreeWidgetItem* item) { choose(item); });
    connect(other, &QPushButton::clicked, this, [this, parents] {
        const QString folder =
            ModalDialog::existingDirectory(this, tr("Replay a trial bundle"), parents.value(0));
        if (!folder.isEmpty()) {
            chosen_ = folder;
            accept();
        }
    });
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(empty);
    layout->addWidget(list_, 1);
    layout->addWidget(buttons);
    resize(760, 460);
}

void BundleChooser::choose(QTreeWidgetItem* item) {
    if (!item || item->data(0, kFolderRole).toString().isEmpty()) {
        return;  // a group's heading
    }
    chosen_ = item->data(0, kFolderRole).toString();
    accept();
}

}  // namespace prisca::app
