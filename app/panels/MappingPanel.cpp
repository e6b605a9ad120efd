#include "app/panels/MappingPanel.h"

#include "app/OperatorText.h"

#include "app/MessageLog.h"

#include "app/LabSession.h"

#include <QCheckBox>
#include <QEvent>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace prisca::app {

namespace {

QString signText(int sign) {
    return sign > 0 ? QStringLiteral("+1") : sign < 0 ? QStringLiteral("−1") : QStringLiteral("0");
}

QBrush signColour(int sign) {
    return sign > 0   ? QBrush(QColor(0xd4, 0xed, 0xda))
           : sign < 0 ? QBrush(QColor(0xf8, 0xd7, 0xda))
                      : QBrush();
}

QString number(double v) {
    return std::isfinite(v) ? QString::number(v, 'g', 2) : QStringLiteral("—");
}

}  // namespace

MappingPanel::MappingPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      signsLabel_(new QLabel(this)),
      signs_(new QTableWidget(this)),
      latencyLabel_(new QLabel(this)),
      latency_(new QSpinBox(this)),
      responseLabel_(new QLabel(this)),
      response_(new QSpinBox(this)),
      nonNegative_(new QCheckBox(this)),
      robust_(new QCheckBox(this)),
      fit_(new QPushButton(this)),
      resultLabel_(new QLabel(this)),
      result_(new QTableWidget(this)),
      warnings_(new QLabel(this)) {
    setObjectName(QStringLiteral("mappingPanel"));
    signs_->setObjectName(QStringLiteral("signs"));
    result_->setObjectName(QStringLiteral("fitResult"));
    warnings_->setObjectName(QStringLiteral("fitWarnings"));
    fit_->setObjectName(QStringLiteral("fitButton"));
    latency_->setObjectName(QStringLiteral("fitLatency"));
    response_->setObjectName(QStringLiteral("fitResponse"));
    latency_->setRange(0, 40);
    response_->setRange(1, 80);
    for (QTableWidget* table : {signs_, result_}) {
        table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
        table->horizontalHeader()->setMinimumSectionSize(30);
        table->setWordWrap(false);
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->setTabKeyNavigation(false);  // Tab moves on to the next control
        table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
        // Rows as tall as their text, no scroll bars: the tables show whole at 1280 x 800.
        table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 4);
        table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    }
    warnings_->setWordWrap(true);
    warnings_->setTextFormat(Qt::PlainText);
    warnings_->setStyleSheet(QStringLiteral("QLabel { color: #9a5600; }"));
    signsLabel_->setWordWrap(true);

    // Compact: the two options on one row, the switches beside Fit B_v (the panel shares the
    // right column with the Run panel at 1280 x 800).
    auto* options = new QHBoxLayout;
    options->addWidget(latencyLabel_);
    options->addWidget(latency_, 1);
    options->addSpacing(8);
    options->addWidget(responseLabel_);
    options->addWidget(response_, 1);
    auto* switches = new QHBoxLayout;
    switches->addWidget(nonNegative_);
    switches->addWidget(robust_);
    switches->addStretch(1);
    switches->addWidget(fit_);
    auto* layout = new QVBoxLayout(this);
    layout->setSpacing(4);
    layout->addWidget(signsLabel_);
    layout->addWidget(signs_);
    layout->addLayout(options);
    layout->addLayout(switches);
    layout->addWidget(resultLabel_);
    layout->addWidget(result_);
    layout->addWidget(warnings_);
    layout->addStretch(1);

    connect(fit_, &QPushButton::clicked, this, &MappingPanel::fit);
    // A click cycles an entry 0 -> +1 -> -1 -> 0.
    connect(signs_, &QTableWidget::cellClicked, this, [this](int row, int column) {
        if (const QTableWidgetItem* item = signs_->item(row, column)) {
            const int sign = item->data(Qt::UserRole).toInt();
            setSign(row, column, sign == 0 ? 1 : sign > 0 ? -1 : 0);
        }
    });
    connect(&session_, &LabSession::plantChanged, this, &MappingPanel::showSession);
    connect(&session_, &LabSession::fitChanged, this, &MappingPanel::showFit);
    retranslateUi();
    showSession();
}

void MappingPanel::fitToRows(QTableWidget* table) {
    // Exactly as tall as its header and rows: no empty strip, no scrolling.
    int height = table->horizontalHeader()->sizeHint().height() + 2 * table->frameWidth();
    for (int r = 0; r < table->rowCount(); ++r) {
        height += table->rowHeight(r);
    }
    table->setFixedHeight(height);
}

void MappingPanel::showSession() {
    const sim::MethodTuning& p = session_.profile();
    const int m = p.info.actionDimension(), n = p.info.stateDimension();
    signs_->clear();
    signs_->setRowCount(m);
    signs_->setColumnCount(n);
    signs_->setHorizontalHeaderLabels(p.info.stateNames);
    signs_->setVerticalHeaderLabels(controlNames(p.info.actionNames));
    for (int l = 0; l < m; ++l) {
        for (int i = 0; i < n; ++i) {
            auto* item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignCenter);
            item->setToolTip(tr("Which way %1 moves %2: +1 increases it, −1 decreases it, 0 not "
                                "at all (B~, eq. 6). Click to change.")
                                 .arg(controlName(p.info.actionNames[l]), p.info.stateNames[i]));
            signs_->setItem(l, i, item);
            setSign(l, i, p.mapping.signs(l, i));
        }
    }
    fitToRows(signs_);
    const core::ActionMappingFitOptions& o = session_.fitOptions();
    latency_->setValue(o.latency);
    response_->setValue(o.responseSteps);
    nonNegative_->setChecked(o.nonNegative);
    robust_->setChecked(o.robust);
    showFit();
}

void MappingPanel::setSign(int control, int state, int sign) {
    if (QTableWidgetItem* item = signs_->item(control, state)) {
        item->setData(Qt::UserRole, sign);
        item->setText(signText(sign));
        item->setBackground(signColour(sign));
    }
}

void MappingPanel::fit() {
    sim::MethodTuning p = session_.profile();
    for (int l = 0; l < signs_->rowCount(); ++l) {
        for (int i = 0; i < signs_->columnCount(); ++i) {
            if (const QTableWidgetItem* item = signs_->item(l, i)) {
                p.mapping.signs(l, i) = item->data(Qt::UserRole).toInt();
            }
        }
    }
    core::ActionMappingFitOptions o = session_.fitOptions();
    o.latency = latency_->value();
    o.responseSteps = response_->value();
    o.nonNegative = nonNegative_->isChecked();
    o.robust = robust_->isChecked();
    // One refit for both changes: the options first (quietly equal if unchanged), then B~.
    session_.setFitOptions(o);
    session_.setProfile(p);
}

void MappingPanel::showFit() {
    const core::ActionMappingFit& f = session_.fit();
    const sim::PlantInfo& info = session_.profile().info;
    const int m = info.actionDimension(), n = info.stateDimension();
    result_->clear();
    result_->setColumnCount(n);
    result_->setRowCount(m + 3);
    // Each state with its unit (B's entries, the residual RMS and the set-aside share are per
    // state), each cell as wide as its number: nothing elided to "0.0...".
    // Name over unit: six states fit the panel's width without scrolling sideways.
    QStringList columns;
    for (int i = 0; i < n; ++i) {
        columns << QStringLiteral("%1\n[%2]").arg(info.stateNames[i], info.stateUnits.value(i));
    }
    result_->setHorizontalHeaderLabels(columns);
    result_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    QStringList rows = controlNames(info.actionNames);
    rows << tr("R²") << tr("RMS") << tr("set aside");
    result_->setVerticalHeaderLabels(rows);
    const auto cell = [&](int row, int column, const QString& text, const QString& tip) {
        auto* item = new QTableWidgetItem(text);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        item->setToolTip(tip);
        result_->setItem(row, column, item);
        return item;
    };
    for (int i = 0; i < n; ++i) {
        for (int l = 0; l < m && f.b.rows() == m; ++l) {
            cell(l, i, f.b(l, i) == 0.0 ? QStringLiteral("·") : number(f.b(l, i)),
                 tr("B[%1, %2] = B_v (.) B~ [%3 per unit of %1, per s]")
                         .arg(controlName(info.actionNames[l]), info.stateNames[i],
                              info.stateUnits[i]) +
                     QStringLiteral(": %1").arg(f.b(l, i), 0, 'g', 6));
        }
        if (f.rSquared.size() == n) {
            cell(m, i, number(f.rSquared[i]),
                 tr("Share of the change of %1 the fit explains").arg(info.stateNames[i]));
            cell(m + 1, i, number(f.residualRms[i]),
                 tr("RMS of what the fit leaves unexplained [%1]").arg(info.stateUnits[i]));
            cell(m + 2, i,
                 f.outlierShare.size() == n
                     ? QStringLiteral("%1%").arg(f.outlierShare[i] * 100.0, 0, 'f', 0)
                     : QStringLiteral("—"),
                 tr("Samples the robust fit set aside (a car sliding, for example)"));
        }
    }
    resultLabel_->setText(tr("Fit on %1 samples:").arg(f.samples));
    if (QTableWidgetItem* rms = result_->verticalHeaderItem(m + 1)) {
        rms->setToolTip(tr("Residual RMS: what the fit leaves unexplained, per state"));
    }
    fitToRows(result_);
    // As wide as its columns: the right column makes room for it rather than scroll sideways.
    result_->resizeColumnsToContents();
    int width = result_->verticalHeader()->width() + 2 * result_->frameWidth();
    for (int c = 0; c < result_->columnCount(); ++c) {
        width += result_->columnWidth(c);
    }
    result_->setMinimumWidth(width);
    QStringList warnings = f.warnings;
    if (!refittingForLanguage_) {
        for (const QString& warning : f.warnings) {
            logMessage(this, tr("Mapping"), MessageLevel::Warning, warning);
        }
    }
    // A negative R² is not a typo: the fit predicts that state's change worse than its mean.
    QStringList below;
    for (int i = 0; i < f.rSquared.size() && i < n; ++i) {
        if (f.rSquared[i] < 0.0) {
            below << info.stateNames[i];
        }
    }
    if (!below.isEmpty()) {
        warnings << tr("R² below zero for %1: the fit predicts the change of that state worse "
                       "than its average does. Check those columns' signs in B~ and the "
                       "latency; a state the controls barely move can also give it.")
                        .arg(below.join(QStringLiteral(", ")));
    }
    for (QString& warning : warnings) {
        warning.prepend(QStringLiteral("⚠ "));
    }
    warnings_->setText(warnings.join(QLatin1Char('\n')));
    warnings_->setVisible(!warnings.isEmpty());
}

void MappingPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        refittingForLanguage_ = true;  // the same warnings: logged once, when they came
        retranslateUi();
        if (!session_.fit().warnings.isEmpty()) {
            session_.refit();  // the fit's own warnings, written in the language now
        }
        refittingForLanguage_ = false;
    }
    QWidget::changeEvent(event);
}

void MappingPanel::retranslateUi() {
    signsLabel_->setText(tr("Intuitive mapping B~ (which way each control moves each state):"));
    latencyLabel_->setText(tr("Latency:"));
    latency_->setSuffix(tr(" steps"));
    latency_->setToolTip(
        tr("Pairs the state change d steps later with each change of action "
           "(eq. 8)."));
    responseLabel_->setText(tr("Response horizon:"));
    response_->setSuffix(tr(" steps"));
    response_->setToolTip(
        tr("How many steps of response the fit looks at: 1 is eq. 5's one-step "
           "model; more sees effects that build up (yaw rate into heading)."));
    nonNegative_->setText(tr("Keep the signs of B~ (B_v ≥ 0)"));
    nonNegative_->setToolTip(tr("An entry the data would make negative is reported and set to 0."));
    robust_->setText(tr("Robust fit"));
    robust_->setToolTip(
        tr("Set aside samples the linear model cannot explain (reweighted least "
           "squares)."));
    fit_->setText(tr("Fit B_v"));
    fit_->setToolTip(tr("Fit B_v to the demonstration with this B~ (eq. 8)"));
    showFit();
}

}  // namespace prisca::app
