#include "app/ControllerPanel.h"

#include "app/LabSession.h"
#include "core/Table1Report.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace prisca::app {

ControllerPanel::ControllerPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      form_(new QFormLayout),
      method_(new QComboBox(this)),
      horizon_(new QSpinBox(this)),
      gamma_(new QDoubleSpinBox(this)),
      beta_(new QDoubleSpinBox(this)),
      automatic_(new QCheckBox(this)),
      stepScale_(new QDoubleSpinBox(this)),
      thetaBound_(new QDoubleSpinBox(this)),
      fromPd_(new QCheckBox(this)),
      gradient_(new QComboBox(this)),
      effort_(new QDoubleSpinBox(this)),
      window_(new QSpinBox(this)),
      pgsdStep_(new QDoubleSpinBox(this)),
      ilcLearning_(new QDoubleSpinBox(this)),
      ilcLead_(new QSpinBox(this)),
      ilcCutoff_(new QDoubleSpinBox(this)),
      featuresLabel_(new QLabel(this)),
      features_(new QTableWidget(this)),
      limitsLabel_(new QLabel(this)),
      limits_(new QTableWidget(this)),
      problem_(new QLabel(this)),
      preset_(new QPushButton(this)) {
    setObjectName(QStringLiteral("controllerPanel"));
    method_->setObjectName(QStringLiteral("method"));
    for (const sim::MethodSpec& spec : sim::MethodCatalog::all()) {
        method_->addItem(spec.label, spec.id);
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
    automatic_->setObjectName(QStringLiteral("priscaAutomatic"));
    stepScale_->setObjectName(QStringLiteral("stepScale"));
    stepScale_->setRange(0.0, 1e4);
    stepScale_->setDecimals(4);
    thetaBound_->setObjectName(QStringLiteral("thetaBound"));
    thetaBound_->setRange(0.0, 1e4);
    thetaBound_->setDecimals(2);
    fromPd_->setObjectName(QStringLiteral("priscaFromPd"));
    gradient_->setObjectName(QStringLiteral("priscaGradient"));
    gradient_->addItem(QString(), static_cast<int>(core::PriscaParameters::Gradient::OneStep));
    gradient_->addItem(QString(), static_cast<int>(core::PriscaParameters::Gradient::ClosedLoop));
    effort_->setObjectName(QStringLiteral("effortWeight"));
    effort_->setRange(0.0, 1e4);
    effort_->setDecimals(3);
    window_->setObjectName(QStringLiteral("matchingWindow"));
    window_->setRange(0, 100000);
    window_->setSuffix(QStringLiteral(" samples"));
    pgsdStep_->setObjectName(QStringLiteral("pgsdStep"));
    pgsdStep_->setRange(0.0, 1e6);
    pgsdStep_->setDecimals(5);
    ilcLearning_->setObjectName(QStringLiteral("ilcLearning"));
    ilcLearning_->setRange(0.0, 100.0);
    ilcLearning_->setDecimals(3);
    ilcLearning_->setSingleStep(0.05);
    ilcLead_->setObjectName(QStringLiteral("ilcLead"));
    ilcLead_->setRange(0, 200);
    ilcLead_->setSuffix(QStringLiteral(" steps"));
    ilcCutoff_->setObjectName(QStringLiteral("ilcCutoff"));
    ilcCutoff_->setRange(0.0, 20.0);
    ilcCutoff_->setDecimals(2);
    ilcCutoff_->setSuffix(QStringLiteral(" Hz"));
    preset_->setObjectName(QStringLiteral("controllerPreset"));
    features_->setObjectName(QStringLiteral("featureScales"));
    limits_->setObjectName(QStringLiteral("actionLimits"));
    problem_->setObjectName(QStringLiteral("controllerProblem"));
    problem_->setWordWrap(true);
    problem_->setStyleSheet(QStringLiteral("color: #b00020"));
    featuresLabel_->setWordWrap(true);
    for (QTableWidget* table : {features_, limits_}) {
        table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
        table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
        table->setMinimumHeight(60);
    }

    // Each field gets its own label object (retranslateUi() fills in the text).
    for (QWidget* field : std::initializer_list<QWidget*>{
             method_, horizon_, gamma_, beta_, automatic_, stepScale_, thetaBound_, fromPd_,
             gradient_, effort_, window_, pgsdStep_, ilcLearning_, ilcLead_, ilcCutoff_}) {
        form_->addRow(new QLabel(this), field);
    }
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form_);
    layout->addWidget(featuresLabel_);
    layout->addWidget(features_);
    layout->addWidget(limitsLabel_);
    layout->addWidget(limits_);
    layout->addWidget(problem_);
    layout->addWidget(preset_);
    layout->addStretch(1);

    connect(method_, &QComboBox::activated, this, &ControllerPanel::apply);
    connect(gradient_, &QComboBox::activated, this, &ControllerPanel::apply);
    connect(fromPd_, &QCheckBox::toggled, this, &ControllerPanel::apply);
    connect(automatic_, &QCheckBox::toggled, this, &ControllerPanel::apply);
    for (QSpinBox* box : {horizon_, window_, ilcLead_}) {
        connect(box, &QSpinBox::valueChanged, this, &ControllerPanel::apply);
    }
    for (QDoubleSpinBox* box :
         {gamma_, beta_, stepScale_, thetaBound_, effort_, pgsdStep_, ilcLearning_, ilcCutoff_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &ControllerPanel::apply);
    }
    connect(features_, &QTableWidget::itemChanged, this, &ControllerPanel::apply);
    connect(limits_, &QTableWidget::itemChanged, this, &ControllerPanel::apply);
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
    automatic_->setChecked(p.priscaAutomatic);
    stepScale_->setValue(p.prisca.stepSize.scale);
    thetaBound_->setValue(p.prisca.thetaBound);
    fromPd_->setChecked(p.priscaFromPd);
    gradient_->setCurrentIndex(gradient_->findData(static_cast<int>(p.prisca.gradient)));
    effort_->setValue(p.prisca.effortWeights.size() ? p.prisca.effortWeights.maxCoeff() : 0.0);
    window_->setValue(p.matchingWindow);
    pgsdStep_->setValue(p.pgsd.stepSize);
    ilcLearning_->setValue(p.ilcLearningScale);
    ilcLead_->setValue(p.ilcLead);
    ilcCutoff_->setValue(p.ilcCutoff);

    const core::FeatureMap& features = editedFeatures();
    const int m = p.info.actionDimension();
    const int count = features.featureCount();
    features_->clear();
    features_->setRowCount(m);
    features_->setColumnCount(count);
    features_->setVerticalHeaderLabels(p.info.actionNames);
    QStringList columns;
    for (int j = 0; j < count; ++j) {
        columns << QStringLiteral("φ%1").arg(j);
    }
    features_->setHorizontalHeaderLabels(columns);
    for (int l = 0; l < m && l < features.channelCount(); ++l) {
        for (int j = 0; j < count; ++j) {
            const core::FeatureTerm& term = features.terms()[l][j];
            const QString name = p.info.stateNames.value(term.index);
            const QString what =
                term.source == core::FeatureTerm::Source::Deviation ? tr("error in %1").arg(name)
                : term.source == core::FeatureTerm::Source::State   ? tr("state %1").arg(name)
                                                                    : tr("constant");
            auto* item = new QTableWidgetItem(QString::number(term.scale, 'g', 6));
            item->setToolTip(tr("Scale of φ%1 of %2: %3 (Algorithm 1, line 3)")
                                 .arg(j)
                                 .arg(p.info.actionNames[l], what));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            features_->setItem(l, j, item);
        }
    }
    limits_->clear();
    limits_->setRowCount(m);
    limits_->setColumnCount(2);
    limits_->setVerticalHeaderLabels(p.info.actionNames);
    limits_->setHorizontalHeaderLabels({tr("lower"), tr("upper")});
    for (int l = 0; l < m; ++l) {
        for (int side = 0; side < 2; ++side) {
            const double v = side == 0 ? p.info.actionLower[l] : p.info.actionUpper[l];
            auto* item = new QTableWidgetItem(QString::number(v, 'g', 6));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            item->setToolTip(tr("The controller saturates %1 to this [%2]")
                                 .arg(p.info.actionNames[l], p.info.actionUnits[l]));
            limits_->setItem(l, side, item);
        }
    }
    problem_->clear();
    enableScales();
    updating_ = false;
}

void ControllerPanel::enableScales() {
    const bool derived =
        session_.profile().priscaAutomatic && session_.method() == QLatin1String("prisca");
    stepScale_->setEnabled(!derived);
    features_->setEnabled(!derived);
}

const core::FeatureMap& ControllerPanel::editedFeatures() const {
    return session_.profile().featuresOf(session_.method());
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
    p.priscaAutomatic = automatic_->isChecked();
    p.prisca.thetaBound = thetaBound_->value();
    p.priscaFromPd = fromPd_->isChecked();
    p.prisca.gradient =
        static_cast<core::PriscaParameters::Gradient>(gradient_->currentData().toInt());
    if (effort_->value() > 0.0) {
        p.prisca.effortWeights =
            Eigen::VectorXd::Constant(p.info.actionDimension(), effort_->value());
    } else {
        p.prisca.effortWeights.resize(0);
    }
    p.matchingWindow = window_->value();
    p.pgsd.stepSize = pgsdStep_->value();
    p.ilcLearningScale = ilcLearning_->value();
    p.ilcLead = ilcLead_->value();
    p.ilcCutoff = ilcCutoff_->value();

    // Feature scales and limits: every cell must be a finite number; limits within the plant's.
    QString problem;
    std::vector<std::vector<core::FeatureTerm>> terms = editedFeatures().terms();
    for (int l = 0; l < features_->rowCount() && l < static_cast<int>(terms.size()); ++l) {
        for (int j = 0; j < features_->columnCount() && j < static_cast<int>(terms[l].size());
             ++j) {
            bool ok = false;
            const double v =
                features_->item(l, j) ? features_->item(l, j)->text().toDouble(&ok) : 0.0;
            if (!ok || !std::isfinite(v)) {
                problem =
                    tr("Feature φ%1 of %2 must be a number.").arg(j).arg(p.info.actionNames[l]);
            } else {
                terms[l][j].scale = v;
            }
        }
    }
    const sim::PlantInfo physical = sim::PlantCatalog::describe(session_.plant());
    for (int l = 0; l < limits_->rowCount() && l < p.info.actionDimension(); ++l) {
        bool okLow = false, okHigh = false;
        const double low = limits_->item(l, 0) ? limits_->item(l, 0)->text().toDouble(&okLow) : 0.0;
        const double high =
            limits_->item(l, 1) ? limits_->item(l, 1)->text().toDouble(&okHigh) : 0.0;
        if (!okLow || !okHigh || !(low < high) || low < physical.actionLower[l] ||
            high > physical.actionUpper[l]) {
            problem = tr("Limits of %1 must be numbers with lower < upper, within [%2, %3].")
                          .arg(p.info.actionNames[l])
                          .arg(physical.actionLower[l])
                          .arg(physical.actionUpper[l]);
        } else {
            p.info.actionLower[l] = low;
            p.info.actionUpper[l] = high;
        }
    }
    problem_->setText(problem);
    if (!problem.isEmpty()) {
        return;  // nothing half-applied; the cell stays for the operator to correct
    }
    if (&p.featuresOf(session_.method()) != &p.features) {  // the method has its own
        p.priscaFeatures = core::FeatureMap(terms);
    } else {
        p.features = core::FeatureMap(terms);
    }
    const QString method = method_->currentData().toString();
    updating_ = true;  // the session echoes the change back; the boxes already show it
    session_.setProfile(p);
    if (method != session_.method()) {
        session_.setMethod(method);
    }
    updating_ = false;
    enableScales();
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
             "PEGASUS, ILC), or the limit: the oracle, which plans on copies of the simulated "
             "plant itself (simulation only)."));
    label(horizon_, tr("Horizon H:"),
          tr("Smoothing horizon H of the nested expectation over the last H steps (eq. 9, 13)."));
    label(gamma_, tr("Depreciation γ:"),
          tr("Rate of inverse depreciation D (eq. 10); Lemma 4.1 needs γ ≥ 0.93 at H = 10."));
    label(beta_, tr("Step rate β:"),
          tr("Rate of the decaying step size α_k = α_0 β / (k + β) (eq. 3)."));
    label(automatic_, tr("Automatic scales:"),
          tr("PRISCA derives its feature scales, α_0 and matching window from the demonstration "
             "and the fit when it starts (each feature of order one over a second of the "
             "manoeuvre; the step a fixed share of a Newton step; a one-second window). Off: the "
             "step scale and feature scales below, the plant's tuned preset."));
    label(stepScale_, tr("Step scale α_0:"),
          tr("α_0 of eq. 3 (the paper uses 1; its right size depends on the units of e, φ and "
             "B)."));
    label(thetaBound_, tr("θ bound:"),
          tr("If above 0, θ is kept in |θ_i| ≤ bound after each update (projected descent); 0 "
             "leaves it free."));
    thetaBound_->setSpecialValueText(tr("none"));
    label(fromPd_, tr("Start from the PD law:"),
          tr("PRISCA's policy is u = u* + the PD law + θᵀφ: θ = 0 already holds the robot on the "
             "path and PRISCA learns a correction (off: θ = 0 is no feedback at all, as in "
             "Algorithm 1)."));
    label(gradient_, tr("Gradient:"),
          tr("One step: eq. 14 as printed (how the next state moves with θ). Closed loop: eq. 4's "
             "chain rule carried over the window through the fitted model and the policy's own "
             "feedback."));
    gradient_->setItemText(0, tr("One step (eq. 14)"));
    gradient_->setItemText(1, tr("Closed loop (eq. 4 over H)"));
    label(effort_, tr("Effort weight R:"),
          tr("The cost also charges the correction's effort, R (θᵀφ)² per control: what makes "
             "learning settle without a θ bound. 0: none."));
    effort_->setSpecialValueText(tr("none"));
    label(window_, tr("Matching window:"),
          tr("How far ahead the least-state-deviation reference may search (eq. 12); 0 searches "
             "the whole demonstration."));
    label(pgsdStep_, tr("PGSD step α:"), tr("The fixed step size of PGSD (no decay)."));
    label(ilcLearning_, tr("ILC learning Γ/Kp:"),
          tr("ILC's learning gain per control, as a share of the PD's Kp: how much of a trial's "
             "error goes into the next trial's feedforward."));
    label(ilcLead_, tr("ILC lead:"),
          tr("The error this many steps later corrects the action now (covers the plant's "
             "delay)."));
    label(ilcCutoff_, tr("ILC Q cutoff:"),
          tr("Zero-phase low-pass on the learned feedforward after each trial; 0 leaves it "
             "unfiltered."));
    ilcLead_->setSuffix(tr(" steps"));
    preset_->setText(tr("Restore the plant's tuned preset"));
    featuresLabel_->setText(tr("Feature scales φ (per control; the policy is u = u* + θᵀφ):"));
    limitsLabel_->setText(tr("Action limits:"));
    horizon_->setSuffix(tr(" steps"));
    beta_->setSuffix(tr(" steps"));
    window_->setSuffix(tr(" samples"));
}

}  // namespace prisca::app
