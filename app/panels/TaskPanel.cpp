#include "app/panels/TaskPanel.h"

#include "app/widgets/ModalDialog.h"

#include "app/MessageLog.h"

#include "app/LabSession.h"
#include "core/DemonstrationCsv.h"
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/plants/PlantParameters.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace prisca::app {

TaskPanel::TaskPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      targetLabel_(new QLabel(this)),
      target_(new QComboBox(this)),
      demonstration_(new QLabel(this)),
      open_(new QPushButton(this)),
      save_(new QPushButton(this)),
      styleLabel_(new QLabel(this)),
      style_(new QComboBox(this)),
      seed_(new QSpinBox(this)),
      scripted_(new QPushButton(this)),
      plantFileLabel_(new QLabel(this)),
      plantFile_(new QLabel(this)),
      openPlantFile_(new QPushButton(this)),
      clearPlantFile_(new QPushButton(this)) {
    setObjectName(QStringLiteral("taskPanel"));
    target_->setObjectName(QStringLiteral("target"));
    for (const QString& name : sim::PlantCatalog::names()) {
        target_->addItem(QString(), name);
    }
    demonstration_->setObjectName(QStringLiteral("demonstrationInfo"));
    demonstration_->setWordWrap(true);
    open_->setObjectName(QStringLiteral("openDemonstration"));
    save_->setObjectName(QStringLiteral("saveDemonstration"));
    scripted_->setObjectName(QStringLiteral("scriptedDemonstration"));
    style_->setObjectName(QStringLiteral("demonstrationStyle"));
    seed_->setObjectName(QStringLiteral("demonstrationSeed"));
    seed_->setRange(0, 999999);
    seed_->setValue(1);

    plantFile_->setObjectName(QStringLiteral("plantFileInfo"));
    plantFile_->setWordWrap(true);
    plantFile_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    openPlantFile_->setObjectName(QStringLiteral("openPlantFile"));
    clearPlantFile_->setObjectName(QStringLiteral("clearPlantFile"));

    auto* form = new QFormLayout;
    form->addRow(targetLabel_, target_);
    auto* plantFile = new QHBoxLayout;
    plantFile->addWidget(plantFile_, 1);
    plantFile->addWidget(openPlantFile_);
    plantFile->addWidget(clearPlantFile_);
    form->addRow(plantFileLabel_, plantFile);
    auto* scripted = new QHBoxLayout;
    scripted->addWidget(style_, 1);
    scripted->addWidget(seed_);
    form->addRow(styleLabel_, scripted);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(open_);
    buttons->addWidget(save_);
    buttons->addWidget(scripted_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(demonstration_);
    layout->addLayout(buttons);
    layout->addStretch(1);

    connect(target_, &QComboBox::activated, this, [this](int index) {
        const QString plant = target_->itemData(index).toString();
        if (plant != session_.plant()) {
            session_.setPlant(plant);
            QSettings().setValue(QStringLiteral("task/plant"), plant);
        }
    });
    connect(open_, &QPushButton::clicked, this, &TaskPanel::askOpen);
    connect(save_, &QPushButton::clicked, this, &TaskPanel::askSave);
    connect(scripted_, &QPushButton::clicked, this, &TaskPanel::useScripted);
    connect(openPlantFile_, &QPushButton::clicked, this, &TaskPanel::askOpenPlantParameters);
    connect(clearPlantFile_, &QPushButton::clicked, this,
            [this] { session_.setPlantParameters(nullptr); });
    connect(&session_, &LabSession::plantParametersChanged, this, &TaskPanel::showPlantParameters);
    connect(&session_, &LabSession::plantChanged, this, [this](const QString& plant) {
        target_->setCurrentIndex(target_->findData(plant));
        fillStyles();
    });
    connect(&session_, &LabSession::demonstrationChanged, this, &TaskPanel::showDemonstration);
    connect(&session_, &LabSession::demonstrationSourceChanged, this,
            &TaskPanel::showDemonstration);
    retranslateUi();
    if (!session_.plant().isEmpty()) {
        target_->setCurrentIndex(target_->findData(session_.plant()));
        fillStyles();
        showDemonstration();
    }
}

QString TaskPanel::styleLabel(const QString& name) {
    // A style's command-line name read in the window's language, part by part
    // ("stick-180-left": stick, 180 degrees, left); English shows the name itself.
    static const char* const kPhrases[] = {QT_TR_NOOP("figure-eight"), QT_TR_NOOP("s-turn"),
                                           QT_TR_NOOP("u-turn"), QT_TR_NOOP("s-bend")};
    static const char* const kWords[] = {
        QT_TR_NOOP("stick"), QT_TR_NOOP("keyboard"), QT_TR_NOOP("standstill"), QT_TR_NOOP("fast"),
        QT_TR_NOOP("slow"),  QT_TR_NOOP("blip"),     QT_TR_NOOP("jitter"),     QT_TR_NOOP("coast"),
        QT_TR_NOOP("left"),  QT_TR_NOOP("right"),    QT_TR_NOOP("swing"),      QT_TR_NOOP("medium"),
        QT_TR_NOOP("small"), QT_TR_NOOP("large"),    QT_TR_NOOP("circle"),     QT_TR_NOOP("wide"),
        QT_TR_NOOP("dock"),  QT_TR_NOOP("spin")};
    QString rest = name;
    QStringList parts;
    bool translated = false;
    while (!rest.isEmpty()) {
        QString part;
        for (const char* phrase : kPhrases) {
            const QString p = QString::fromLatin1(phrase);
            if (rest.startsWith(p) && (rest.size() == p.size() || rest[p.size()] == u'-')) {
                part = p;
            }
        }
        if (part.isEmpty()) {
            part = rest.section(QLatin1Char('-'), 0, 0);
        }
        rest = rest.mid(part.size() + 1);
        bool number = false;
        part.toInt(&number);
        QString shown = number ? tr("%1°").arg(part) : part;
        for (const char* word : kPhrases) {
            shown = part == QLatin1String(word) ? tr(word) : shown;
        }
        for (const char* word : kWords) {
            shown = part == QLatin1String(word) ? tr(word) : shown;
        }
        translated = translated || (!number && shown != part);
        parts << shown;
    }
    return translated ? parts.join(QLatin1Char(' ')) : name;
}

void TaskPanel::fillStyles() {
    style_->clear();
    for (const sim::DemonstrationStyle& style : sim::DemonstrationStyles::of(session_.plant())) {
        style_->addItem(styleLabel(style.name), style.name);
        style_->setItemData(style_->count() - 1, style.description, Qt::ToolTipRole);
    }
    style_->setCurrentIndex(std::max(0, style_->findData(session_.scriptedStyle())));
    seed_->setValue(static_cast<int>(session_.scriptedSeed()));
}

void TaskPanel::useScripted() {
    const QString style = style_->currentData().toString();
    try {
        session_.setScriptedDemonstration(style, static_cast<std::uint64_t>(seed_->value()));
    } catch (const std::exception& e) {
        warningBox(this, tr("Scripted demonstration"), QString::fromStdString(e.what()));
    }
}

bool TaskPanel::openDemonstration(const QString& path) {
    core::FileError error;
    auto demo = core::readDemonstrationCsv(path, &error);
    if (!demo) {
        warningBox(this, tr("Open demonstration"),
                   tr("The demonstration could not be read.\n\n%1").arg(error.toString()));
        return false;
    }
    try {
        session_.setDemonstration(std::make_shared<core::Demonstration>(std::move(*demo)), path);
    } catch (const std::exception& e) {
        warningBox(this, tr("Open demonstration"),
                   tr("%1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    QSettings().setValue(QStringLiteral("task/lastDirectory"), QFileInfo(path).absolutePath());
    return true;
}

bool TaskPanel::openPlantParameters(const QString& path) {
    QString error;
    auto parameters = sim::readPlantParameters(path, session_.plant(), &error);
    if (!parameters) {
        warningBox(this, tr("Open plant file"),
                   tr("The plant file could not be used.\n\n%1").arg(error));
        return false;
    }
    try {
        session_.setPlantParameters(
            std::make_shared<const sim::PlantParameters>(std::move(*parameters)));
    } catch (const std::exception& e) {
        warningBox(this, tr("Open plant file"),
                   tr("%1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    QSettings().setValue(QStringLiteral("task/plantFileDirectory"), QFileInfo(path).absolutePath());
    return true;
}

void TaskPanel::askOpenPlantParameters() {
    const QString path = ModalDialog::openFileName(
        this, tr("Open plant file"), QSettings().value("task/plantFileDirectory").toString(),
        tr("Plant files (*.json);;All files (*)"));
    if (!path.isEmpty()) {
        openPlantParameters(path);
    }
}

void TaskPanel::showPlantParameters() {
    const auto parameters = session_.plantParameters();
    clearPlantFile_->setEnabled(parameters != nullptr);
    if (!parameters) {
        plantFile_->setText(tr("the catalog's"));
        plantFile_->setToolTip(QString());
        return;
    }
    plantFile_->setText(QFileInfo(parameters->source).fileName());
    plantFile_->setToolTip(QStringLiteral("%1\n\n%2")
                               .arg(QDir::toNativeSeparators(parameters->source),
                                    sim::plantParametersText(*parameters)));
}

void TaskPanel::askOpen() {
    const QString path = ModalDialog::openFileName(
        this, tr("Open demonstration"), QSettings().value("task/lastDirectory").toString(),
        tr("Demonstrations (*.csv);;All files (*)"));
    if (!path.isEmpty()) {
        openDemonstration(path);
    }
}

void TaskPanel::askSave() {
    const QString path = ModalDialog::saveFileName(
        this, tr("Save demonstration"), QSettings().value("task/lastDirectory").toString(),
        tr("Demonstrations (*.csv)"));
    if (path.isEmpty()) {
        return;
    }
    core::FileError error;
    if (!core::writeDemonstrationCsv(*session_.demonstration(), path, &error)) {
        warningBox(this, tr("Save demonstration"), error.toString());
        return;
    }
    session_.setDemonstrationSource(path);  // from now on it is named by its saved file
}

void TaskPanel::showDemonstration() {
    const auto demo = session_.demonstration();
    if (!demo) {
        demonstration_->clear();
        return;
    }
    const QString source = session_.demonstrationSource().isEmpty()
                               ? tr("the scripted operator (%1, seed %2)")
                                     .arg(styleLabel(session_.scriptedStyle()))
                                     .arg(session_.scriptedSeed())
                               : QFileInfo(session_.demonstrationSource()).fileName();
    demonstration_->setText(tr("Demonstration: %1 samples, %2 s at %3 Hz, from %4.")
                                .arg(demo->length())
                                .arg(demo->length() * demo->dt, 0, 'f', 1)
                                .arg(1.0 / demo->dt, 0, 'f', 0)
                                .arg(source));
}

void TaskPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void TaskPanel::retranslateUi() {
    targetLabel_->setText(tr("Target:"));
    if (!session_.plant().isEmpty()) {
        const QSignalBlocker quiet(style_);  // relabelled, not a new choice
        fillStyles();
    }
    for (int i = 0; i < target_->count(); ++i) {
        const QString name = target_->itemData(i).toString();
        const sim::PlantEntry* entry = sim::PlantCatalog::find(name);
        target_->setItemText(
            i, entry ? QCoreApplication::translate("PlantCatalog", entry->displayName) : name);
    }
    open_->setText(tr("Open..."));
    open_->setToolTip(tr("Open a demonstration CSV recorded earlier"));
    save_->setText(tr("Save as..."));
    save_->setToolTip(tr("Save the demonstration as CSV"));
    styleLabel_->setText(tr("Scripted operator:"));
    style_->setToolTip(
        tr("How the scripted operator demonstrates: keys or stick, left or right, "
           "how far and how fast (hover over a style for its description)"));
    seed_->setToolTip(tr("Seed of the operator's hand variation"));
    seed_->setPrefix(tr("seed "));
    plantFileLabel_->setText(tr("Physical parameters:"));
    openPlantFile_->setText(tr("Load..."));
    openPlantFile_->setToolTip(
        tr("Load a plant file: the car's mass, wheelbase, grip, motor, steering and servo "
           "(prisca-cli plant --plant NAME --print-params --format json writes one to edit)"));
    clearPlantFile_->setText(tr("Catalog"));
    clearPlantFile_->setToolTip(tr("Go back to the catalog's plant"));
    showPlantParameters();
    scripted_->setText(tr("Use scripted"));
    scripted_->setToolTip(
        tr("Use the scripted operator's demonstration in the chosen style and seed"));
    showDemonstration();
}

}  // namespace prisca::app
