#include "app/ControllerPanel.h"

#include "app/LabSession.h"
#include "core/Table1Report.h"
#include "sim/ControllerFactory.h"
#include "sim/PlantCatalog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace prisca::app {

ControllerPanel::ControllerPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      form_(new QFormLayout),
      method_(new QComboBox(this)),
      horizon_(new QSpinBox(this)),
      gamma_(new QDoubleSpinBox(this)),
      beta_(new QDoubleSpinBox(this)),
      stepScale_(new QDoubleSpinBox(this)),
      thetaBound_(new QDoubleSpinBox(this)),
      window_(new QSpinBox(this)),
      pgsdStep_(new QDoubleSpinBox(this)),
      preset_(new QPushButton(this)) {
    setObjectName(QStringLiteral("controllerPanel"));
    method_->setObjectName(QStringLiteral("method"));
    for (const QString& method : sim::ControllerFactory::methods()) {
        method_->addItem(core::table1Label(method), method);
    }
    horizon_->setObjectName(QStringLiteral("horizon"));
    horizon_->setRange(1, 200);
    horizon_->setSuffix(QStringLiteral(" steps"));
    gamma_->setObjectName(QStringLiteral("gamma"));
    gamma_->setRange(0.0, 1.0);
    gamma_->setDecimals(3);
    gamma_->setSingleStep(0.01);
    beta_->setObjectName(QStringLiteral("beta"));
    beta_->setRange(1.0, 1e7);
    beta_->setDecimals(0);
    beta_->setSingleStep(100);
    beta_->setSuffix(QStringLiteral(" steps"));
    stepScale_->setObjectName(QStringLiteral("stepScale"));
    stepScale_->setRange(0.0, 1e4);
    stepScale_->setDecimals(4);
    thetaBound_->setObjectName(QStringLiteral("thetaBound"));
    thetaBound_->setRange(0.0, 1e4);
    thetaBound_->setDecimals(2);
    window_->setObjectName(QStringLiteral("matchingWindow"));
    window_->setRange(0, 100000);
    window_->setSuffix(QStringLiteral(" samples"));
    pgsdStep_->setObjectName(QStringLiteral("pgsdStep"));
    pgsdStep_->setRange(0.0, 1e6);
    pgsdStep_->setDecimals(5);
    preset_->setObjectName(QStringLiteral("controllerPreset"));

    form_->addRow(QString(), method_);
    form_->addRow(QString(), horizon_);
    form_->addRow(QString(), gamma_);
    form_->addRow(QString(), beta_);
    form_->addRow(QString(), stepScale_);
    form_->addRow(QString(), thetaBound_);
    form_->addRow(QString(), window_);
    form_->addRow(QString(), pgsdStep_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form_);
    layout->addWidget(preset_);
    layout->addStretch(1);

    connect(method_, &QComboBox::activated, this, &ControllerPanel::apply);
    for (QSpinBox* box : {horizon_, window_}) {
        connect(box, &QSpinBox::valueChanged, this, &ControllerPanel::apply);
    }
    for (QDoubleSpinBox* box : {gamma_, beta_, stepScale_, thetaBound_, pgsdStep_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &ControllerPanel::apply);
    }
    connect(preset_, &QPushButton::clicked, this, [this] {
        sim::PlantProfile preset = sim::PlantProfile::forPlant(session_.profile().info);
        preset.mapping = session_.profile().mapping;  // the operator's B~ is not a parameter
        session_.setProfile(preset);
    });
    connect(&session_, &LabSession::controllerChanged, this, &ControllerPanel::showSession);
    retranslateUi();
    showSession();
}

void ControllerPanel::showSession() {
    updating_ = true;
    const sim::PlantProfile& p = session_.profile();
    method_->setCurrentIndex(method_->findData(session_.method()));
    horizon_->setValue(p.prisca.horizon);
    gamma_->setValue(p.prisca.gamma);
    beta_->setValue(p.prisca.stepSize.beta);
    stepScale_->setValue(p.prisca.stepSize.scale);
    thetaBound_->setValue(p.prisca.thetaBound);
    window_->setValue(p.matchingWindow);
    pgsdStep_->setValue(p.pgsd.stepSize);
    updating_ = false;
}

void ControllerPanel::apply() {
    if (updating_ || session_.plant().isEmpty()) {
        return;
    }
    sim::PlantProfile p = session_.profile();
    p.prisca.horizon = horizon_->value();
    p.prisca.gamma = gamma_->value();
    p.prisca.stepSize.beta = beta_->value();
    p.prisca.stepSize.scale = stepScale_->value();
    p.prisca.thetaBound = thetaBound_->value();
    p.matchingWindow = window_->value();
    p.pgsd.stepSize = pgsdStep_->value();
    const QString method = method_->currentData().toString();
    updating_ = true;  // the session echoes the change back; the boxes already show it
    session_.setProfile(p);
    if (method != session_.method()) {
        session_.setMethod(method);
    }
    updating_ = false;
}

void ControllerPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void ControllerPanel::retranslateUi() {
    const auto label = [this](QWidget* field, const QString& text, const QString& tip) {
        if (auto* l = qobject_cast<QLabel*>(form_->labelForField(field))) {
            l->setText(text);
            l->setToolTip(tip);
        }
        field->setToolTip(tip);
    };
    label(method_, tr("Method:"),
          tr("PRISCA, or a comparison method of Table I (PD family, action playback, PGSD, "
             "PEGASUS)."));
    label(horizon_, tr("Horizon H:"),
          tr("Smoothing horizon H of the nested expectation over the last H steps (eq. 9, 13)."));
    label(gamma_, tr("Depreciation γ:"),
          tr("Rate of inverse depreciation D (eq. 10); Lemma 4.1 needs γ ≥ 0.93 at H = 10."));
    label(beta_, tr("Step rate β:"),
          tr("Rate of the decaying step size α_k = α_0 β / (k + β) (eq. 3)."));
    label(stepScale_, tr("Step scale α_0:"),
          tr("α_0 of eq. 3 (the paper uses 1; its right size depends on the units of e, φ and "
             "B)."));
    label(thetaBound_, tr("θ bound:"),
          tr("If above 0, θ is kept in |θ_i| ≤ bound after each update (projected descent); 0 "
             "leaves it free."));
    label(window_, tr("Matching window:"),
          tr("How far ahead the least-state-deviation reference may search (eq. 12); 0 searches "
             "the whole demonstration."));
    label(pgsdStep_, tr("PGSD step α:"), tr("The fixed step size of PGSD (no decay)."));
    preset_->setText(tr("Restore the plant's tuned preset"));
    horizon_->setSuffix(tr(" steps"));
    beta_->setSuffix(tr(" steps"));
    window_->setSuffix(tr(" samples"));
}

}  // namespace prisca::app
