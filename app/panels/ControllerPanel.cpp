#include "app/panels/ControllerPanel.h"

#include "app/OperatorText.h"

#include "app/MessageLog.h"

#include "app/LabSession.h"
#include "core/Table1Report.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace prisca::app {

QString ControllerPanel::unitText(const char* unit) {
    // Words are translated; symbols (s, Hz, m) stay as they are in every language.
    const QString u = QString::fromUtf8(unit);
    if (u == QLatin1String("steps")) {
        return tr("steps");
    }
    if (u == QLatin1String("samples")) {
        return tr("samples");
    }
    return u;
}

ControllerPanel::ControllerPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      form_(new QFormLayout),
      method_(new QComboBox(this)),
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

    form_->addRow(new QLabel(this), method_);
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
    connect(features_, &QTableWidget::itemChanged, this, &ControllerPanel::apply);
    connect(limits_, &QTableWidget::itemChanged, this, &ControllerPanel::apply);
    connect(preset_, &QPushButton::clicked, this, [this] {
        sim::MethodTuning preset = sim::PlantCatalog::tuning(session_.profile().info);
        preset.mapping = session_.profile().mapping;  // the operator's B~ is not a parameter
        session_.setProfile(preset);
    });
    connect(&session_, &LabSession::controllerChanged, this, &ControllerPanel::showSession);
    retranslateUi();
    showSession();
}

void ControllerPanel::buildEditors() {
    const QString key = session_.method() + QLatin1Char('@') + session_.plant();
    if (key == editorsFor_) {
        return;
    }
    editorsFor_ = key;
    for (const Editor& editor : editors_) {
        form_->removeRow(editor.label);  // deletes the label and the field
    }
    editors_.clear();
    const sim::MethodSpec* spec = sim::MethodCatalog::find(session_.method());
    if (!spec) {
        return;
    }
    const sim::PlantInfo& info = session_.profile().info;
    for (const sim::MethodParameter& parameter : spec->parameters) {
        Editor editor;
        editor.parameter = &parameter;
        editor.label = new QLabel(this);
        const QString name = QString::fromLatin1(parameter.name);
        const int count = parameter.perChannel ? info.actionDimension() : 1;
        for (int l = 0; l < count; ++l) {
            QWidget* field = nullptr;
            switch (parameter.kind) {
                case sim::MethodParameter::Kind::Switch: {
                    auto* box = new QCheckBox(this);
                    connect(box, &QCheckBox::toggled, this, &ControllerPanel::apply);
                    field = box;
                    break;
                }
                case sim::MethodParameter::Kind::Choice: {
                    auto* box = new QComboBox(this);
                    for (const char* choice : parameter.choices) {
                        box->addItem(QString::fromLatin1(choice));
                    }
                    connect(box, &QComboBox::activated, this, &ControllerPanel::apply);
                    field = box;
                    break;
                }
                case sim::MethodParameter::Kind::Integer: {
                    auto* box = new QSpinBox(this);
                    box->setRange(static_cast<int>(parameter.minimum),
                                  static_cast<int>(parameter.maximum));
                    connect(box, &QSpinBox::valueChanged, this, &ControllerPanel::apply);
                    field = box;
                    break;
                }
                case sim::MethodParameter::Kind::Real: {
                    auto* box = new QDoubleSpinBox(this);
                    box->setRange(parameter.minimum, parameter.maximum);
                    box->setDecimals(parameter.decimals);
                    connect(box, &QDoubleSpinBox::valueChanged, this, &ControllerPanel::apply);
                    field = box;
                    break;
                }
            }
            field->setObjectName(parameter.perChannel ? QStringLiteral("%1[%2]").arg(name).arg(l)
                                                      : name);
            editor.fields.push_back(field);
        }
        if (editor.fields.size() == 1) {
            form_->addRow(editor.label, editor.fields.front());
        } else {
            // One box per control, one line each, labelled with its control's name (side by
            // side they would push the panel wider than its dock).
            auto* row = new QWidget(this);
            row->setObjectName(name);
            auto* boxes = new QGridLayout(row);
            boxes->setContentsMargins(0, 0, 0, 0);
            for (size_t l = 0; l < editor.fields.size(); ++l) {
                const int line = static_cast<int>(l);
                boxes->addWidget(new QLabel(controlName(info.actionNames.value(line)), row), line,
                                 0);
                QWidget* field = editor.fields[l];
                field->setParent(row);
                // The width the row has, not that of the range's largest number.
                field->setSizePolicy(QSizePolicy::Ignored, field->sizePolicy().verticalPolicy());
                field->setMinimumWidth(
                    fontMetrics().horizontalAdvance(QStringLiteral("00.000000")) + 30);
                boxes->addWidget(field, line, 1);
            }
            boxes->setColumnStretch(1, 1);
            form_->addRow(editor.label, row);
        }
        editors_.push_back(editor);
    }
    retranslateUi();
}

void ControllerPanel::showSession() {
    updating_ = true;
    buildEditors();
    const sim::MethodTuning& p = session_.profile();
    method_->setCurrentIndex(method_->findData(session_.method()));
    for (const Editor& editor : editors_) {
        const Eigen::VectorXd value = editor.parameter->value(p);
        for (size_t l = 0; l < editor.fields.size() && static_cast<Eigen::Index>(l) < value.size();
             ++l) {
            QWidget* field = editor.fields[l];
            if (auto* box = qobject_cast<QCheckBox*>(field)) {
                box->setChecked(value[l] != 0.0);
            } else if (auto* combo = qobject_cast<QComboBox*>(field)) {
                combo->setCurrentIndex(static_cast<int>(value[l]));
            } else if (auto* spin = qobject_cast<QSpinBox*>(field)) {
                spin->setValue(static_cast<int>(value[l]));
            } else if (auto* real = qobject_cast<QDoubleSpinBox*>(field)) {
                real->setValue(value[l]);
            }
        }
    }

    const core::FeatureMap& features = editedFeatures();
    const int m = p.info.actionDimension();
    const int count = features.featureCount();
    features_->clear();
    features_->setRowCount(m);
    features_->setColumnCount(count);
    features_->setVerticalHeaderLabels(controlNames(p.info.actionNames));
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
                                 .arg(controlName(p.info.actionNames[l]), what));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            features_->setItem(l, j, item);
        }
    }
    limits_->clear();
    limits_->setRowCount(m);
    limits_->setColumnCount(2);
    limits_->setVerticalHeaderLabels(controlNames(p.info.actionNames));
    limits_->setHorizontalHeaderLabels({tr("lower"), tr("upper")});
    for (int l = 0; l < m; ++l) {
        for (int side = 0; side < 2; ++side) {
            const double v = side == 0 ? p.info.actionLower[l] : p.info.actionUpper[l];
            auto* item = new QTableWidgetItem(QString::number(v, 'g', 6));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            item->setToolTip(tr("The controller saturates %1 to this [%2]")
                                 .arg(controlName(p.info.actionNames[l]), p.info.actionUnits[l]));
            limits_->setItem(l, side, item);
        }
    }
    problem_->clear();
    const sim::MethodSpec* spec = sim::MethodCatalog::find(session_.method());
    const bool showFeatures = spec && spec->usesFeatures;  // the others have no theta^T phi
    featuresLabel_->setVisible(showFeatures);
    features_->setVisible(showFeatures);
    enableScales();
    updating_ = false;
}

void ControllerPanel::enableScales() {
    // A start from the demonstration derives the PD law (its gains and smoothing are not
    // used) and makes PRISCA take its automatic scales.
    const bool startsFromLaw = std::any_of(editors_.begin(), editors_.end(), [](const Editor& e) {
        return QLatin1String(e.parameter->name) == QLatin1String("start");
    });
    const bool demoStart =
        startsFromLaw && session_.profile().start == sim::MethodTuning::Start::Demonstration;
    const bool derived = (session_.profile().priscaAutomatic || demoStart) &&
                         session_.method() == QLatin1String("prisca");
    for (const Editor& editor : editors_) {
        const QLatin1String name(editor.parameter->name);
        const bool unused =
            name == QLatin1String("prisca.alpha0")
                ? derived
                : demoStart && (name == QLatin1String("pd.kp") || name == QLatin1String("pd.kd") ||
                                name == QLatin1String("pd.H"));
        for (QWidget* field : editor.fields) {
            field->setEnabled(!unused);
        }
    }
    features_->setEnabled(!derived);
}

const core::FeatureMap& ControllerPanel::editedFeatures() const {
    return sim::MethodCatalog::featuresOf(session_.profile(), session_.method());
}

void ControllerPanel::apply() {
    if (updating_ || session_.plant().isEmpty()) {
        return;
    }
    sim::MethodTuning p = session_.profile();
    const QString method = method_->currentData().toString();
    if (method != session_.method()) {
        // A new method shows its own parameters: switch first, then edits apply to it.
        session_.setMethod(method);
        return;
    }
    // Only the value the operator changed: the others keep what the session holds (a box
    // rounds to its decimals, and writing it back would change a value nobody touched).
    const QObject* source = sender();
    for (const Editor& editor : editors_) {
        const auto at = std::find(editor.fields.begin(), editor.fields.end(), source);
        if (at == editor.fields.end()) {
            continue;
        }
        Eigen::VectorXd value = editor.parameter->value(p);
        const Eigen::Index l = at - editor.fields.begin();
        if (l >= value.size()) {
            continue;
        }
        if (auto* box = qobject_cast<QCheckBox*>(*at)) {
            value[l] = box->isChecked() ? 1.0 : 0.0;
        } else if (auto* combo = qobject_cast<QComboBox*>(*at)) {
            value[l] = combo->currentIndex();
        } else if (auto* spin = qobject_cast<QSpinBox*>(*at)) {
            value[l] = spin->value();
        } else if (auto* real = qobject_cast<QDoubleSpinBox*>(*at)) {
            value[l] = real->value();
        }
        try {
            editor.parameter->assign(p, value);
        } catch (const std::invalid_argument& e) {
            showStatus(problem_, tr("Controller"), QString::fromUtf8(e.what()),
                       MessageLevel::Warning);
            return;  // nothing applied
        }
    }

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
                problem = tr("Feature φ%1 of %2 must be a number.")
                              .arg(j)
                              .arg(controlName(p.info.actionNames[l]));
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
                          .arg(controlName(p.info.actionNames[l]))
                          .arg(physical.actionLower[l])
                          .arg(physical.actionUpper[l]);
        } else {
            p.info.actionLower[l] = low;
            p.info.actionUpper[l] = high;
        }
    }
    if (problem.isEmpty()) {
        problem_->clear();
    } else {
        showStatus(problem_, tr("Controller"), problem, MessageLevel::Warning);
    }
    if (!problem.isEmpty()) {
        return;  // nothing half-applied; the cell stays for the operator to correct
    }
    if (&sim::MethodCatalog::featuresOf(p, session_.method()) !=
        &p.features) {  // the method has its own
        p.priscaFeatures = core::FeatureMap(terms);
    } else {
        p.features = core::FeatureMap(terms);
    }
    updating_ = true;  // the session echoes the change back; the boxes already show it
    session_.setProfile(p);
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
    if (limits_->columnCount() == 2) {
        limits_->setHorizontalHeaderLabels({tr("lower"), tr("upper")});
    }
    const auto label = [this](QWidget* field, QLabel* l, const QString& text, const QString& tip) {
        if (l) {
            l->setText(text);
            l->setToolTip(tip);
        }
        field->setToolTip(tip);
    };
    label(method_, qobject_cast<QLabel*>(form_->labelForField(method_)), tr("Method:"),
          tr("PRISCA, or a comparison method of Table I (PD family, LQR, action playback, PGSD, "
             "PEGASUS, ILC), or the limit: the oracle, which plans on copies of the simulated "
             "plant itself (simulation only)."));
    for (const Editor& editor : editors_) {
        const sim::MethodParameter& p = *editor.parameter;
        const QString help = QCoreApplication::translate("MethodParameter", p.help);
        const QString tip =
            QStringLiteral("%1 (%2, %3)").arg(help, QString::fromLatin1(p.name), p.range());
        QString text = QCoreApplication::translate("MethodParameter", p.label);
        const QString unit = unitText(p.unit);
        if (p.perChannel && !unit.isEmpty()) {
            text += QStringLiteral(" [%1]").arg(unit);
        }
        label(editor.fields.front(), editor.label, text + QLatin1Char(':'), tip);
        for (QWidget* field : editor.fields) {
            // The unit after the number (per channel, the label says it), in this language.
            const QString suffix =
                unit.isEmpty() || p.perChannel ? QString() : QLatin1Char(' ') + unit;
            if (auto* box = qobject_cast<QSpinBox*>(field)) {
                box->setSuffix(suffix);
            } else if (auto* real = qobject_cast<QDoubleSpinBox*>(field)) {
                real->setSuffix(suffix);
            }
            field->setToolTip(tip);
            if (p.zeroMeans) {
                if (auto* real = qobject_cast<QDoubleSpinBox*>(field)) {
                    real->setSpecialValueText(
                        QCoreApplication::translate("MethodParameter", p.zeroMeans));
                }
            }
        }
    }
    preset_->setText(tr("Restore the plant's tuned preset"));
    featuresLabel_->setText(tr("Feature scales φ (per control; the policy is u = u* + θᵀφ):"));
    limitsLabel_->setText(tr("Action limits:"));
}

}  // namespace prisca::app
