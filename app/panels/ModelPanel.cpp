#include "app/panels/ModelPanel.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/MessageLog.h"
#include "app/OperatorText.h"
#include "app/plot/FigureFile.h"
#include "sim/PlantCatalog.h"

#include <QCoreApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QResizeEvent>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <stdexcept>

namespace prisca::app {

namespace {

QString unitText(const QString& unit) {
    return unit == QLatin1String("1") ? QString() : unit;
}

QString centimetres(double metres) {
    return QString::number(100.0 * metres, 'f', 2);
}

}  // namespace

ModelPanel::ModelPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      emergency_(emergency),
      identification_(new IdentificationThread(this)),
      intro_(new QLabel(this)),
      identify_(new QPushButton(this)),
      cancel_(new QPushButton(this)),
      progress_(new QProgressBar(this)),
      status_(new QLabel(this)),
      summary_(new QLabel(this)),
      figureView_(new QLabel(this)),
      table_(new QTableWidget(this)),
      held_(new QLabel(this)),
      ticker_(new QTimer(this)) {
    setObjectName(QStringLiteral("modelPanel"));
    qRegisterMetaType<IdentificationRequest>();
    qRegisterMetaType<std::shared_ptr<const sim::IdentificationResult>>();
    identify_->setObjectName(QStringLiteral("identifyButton"));
    cancel_->setObjectName(QStringLiteral("cancelIdentify"));
    progress_->setObjectName(QStringLiteral("identifyProgress"));
    status_->setObjectName(QStringLiteral("modelStatus"));
    summary_->setObjectName(QStringLiteral("modelSummary"));
    figureView_->setObjectName(QStringLiteral("modelFigure"));
    table_->setObjectName(QStringLiteral("modelParameters"));
    held_->setObjectName(QStringLiteral("modelHeld"));
    for (QLabel* label : {intro_, status_, summary_, held_}) {
        label->setWordWrap(true);
        label->setTextFormat(Qt::PlainText);
    }
    held_->setStyleSheet(QStringLiteral("QLabel { color: #555; }"));
    progress_->setRange(0, 1);
    progress_->setValue(0);
    progress_->setTextVisible(false);  // no "0 %" before anything ran
    figureView_->setAlignment(Qt::AlignCenter);
    figureView_->setMinimumSize(200, 180);
    figureView_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    figureView_->installEventFilter(this);
    table_->setColumnCount(5);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setTabKeyNavigation(false);      // Tab moves on to the next control
    table_->setFocusPolicy(Qt::ClickFocus);  // read, not edited: never handed the focus
    table_->setWordWrap(false);
    table_->verticalHeader()->setVisible(false);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 4);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    // As tall as its rows: the panel scrolls, not the table inside it.
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(identify_);
    buttons->addWidget(cancel_);
    buttons->addWidget(progress_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setSpacing(4);
    layout->addWidget(intro_);
    layout->addLayout(buttons);
    layout->addWidget(status_);
    layout->addWidget(summary_);
    layout->addWidget(figureView_);
    layout->addWidget(table_);
    layout->addWidget(held_);
    layout->addStretch(1);

    connect(identification_, &IdentificationThread::progress, this,
            [this](int id, long long done, long long total) {
                if (id != requestId_ || !running_) {
                    return;  // a report that crossed the end
                }
                done_ = std::min(done, total);
                total_ = total;
                showProgress();
            });
    connect(identification_, &IdentificationThread::finished, this, &ModelPanel::showResult);
    connect(identification_, &IdentificationThread::failed, this,
            [this](int id, const QString& message) {
                if (id != requestId_) {
                    return;
                }
                setRunning(false);
                identifying_.reset();
                warningBox(this, tr("Model"), tr("The identification failed: %1").arg(message));
                status_->setText(tr("The identification failed: %1").arg(message));
                emit finished();
            });
    ticker_->setInterval(1000);  // the time so far, even between reports
    connect(ticker_, &QTimer::timeout, this, &ModelPanel::showProgress);
    connect(identify_, &QPushButton::clicked, this, &ModelPanel::identify);
    connect(cancel_, &QPushButton::clicked, this, &ModelPanel::cancel);
    connect(&emergency_, &EmergencyStop::latchChanged, this, [this] { setRunning(running_); });
    connect(&emergency_, &EmergencyStop::engaged, this, [this] {
        if (running_ && !stoppedByEmergency_) {
            stoppedByEmergency_ = true;
            identification_->cancel();
            showStatus(status_, tr("Model"),
                       tr("E-STOP: the identification is cancelled; the session keeps the model "
                          "it had."));
        }
    });
    connect(&session_, &LabSession::identifiedModelChanged, this, [this](const QString& reason) {
        if (!reason.isEmpty()) {
            // Said once, as it happened: the model is gone because of what the operator did.
            showStatus(status_, tr("Model"),
                       tr("The identified model was cleared: %1. Identify again for mpc to plan "
                          "through a model of this car.")
                           .arg(reason),
                       MessageLevel::Warning);
        }
        showModel();
    });
    // Another demonstration or car: an identification under way is of the old one.
    const auto dataChanged = [this] {
        if (running_) {
            identification_->cancel();
        }
        setRunning(running_);
        showModel();
    };
    connect(&session_, &LabSession::demonstrationChanged, this, dataChanged);
    connect(&session_, &LabSession::plantChanged, this, dataChanged);
    connect(&session_, &LabSession::plantParametersChanged, this, dataChanged);
    retranslateUi();
    setRunning(false);
}

ModelPanel::~ModelPanel() {
    delete identification_;  // its thread ends (cancelled, bounded wait) before the widgets go
}

void ModelPanel::setIdentificationSettings(const sim::IdentificationSettings& settings) {
    settings_ = settings;
    if (session_.identifiedModel()) {
        showModel();  // the replay with the physics steps of these settings
    }
}

void ModelPanel::identify() {
    if (running_) {
        return;
    }
    if (emergency_.isLatched()) {
        showStatus(status_, tr("Model"), emergency_.refusal());
        return;
    }
    if (!sim::identificationAvailable(session_.plant())) {
        showModel();  // says why not
        return;
    }
    IdentificationRequest request;
    request.id = ++requestId_;
    request.demonstration = session_.demonstration();
    request.prior = session_.identificationPrior();
    request.settings = settings_;
    identifying_ = request.demonstration;
    stoppedByEmergency_ = false;
    done_ = total_ = 0;
    progress_->setRange(0, 0);  // busy until the first count arrives
    progress_->resetFormat();
    progress_->setTextVisible(true);
    clock_.start();
    setRunning(true);
    ticker_->start();
    showStatus(status_, tr("Model"),
               tr("Identifying the car from %1...").arg(session_.demonstrationDescription()));
    identification_->start(request);
}

void ModelPanel::cancel() {
    if (running_ && !identification_->isCancelled()) {
        identification_->cancel();
        showStatus(status_, tr("Model"), tr("Cancelling the identification..."));
    }
}

void ModelPanel::setRunning(bool running) {
    running_ = running;
    if (!running) {
        ticker_->stop();
    }
    const bool available = sim::identificationAvailable(session_.plant());
    const bool canIdentify = !running && available && !emergency_.isLatched();
    // The button pressed hands the focus to the one that takes over before it is disabled: Qt
    // would give it to the next field, and the panel would scroll away from the progress.
    if (running) {
        cancel_->setEnabled(true);
        if (identify_->hasFocus()) {
            cancel_->setFocus();
        }
    } else if (canIdentify) {
        identify_->setEnabled(true);
        if (cancel_->hasFocus()) {
            identify_->setFocus();
        }
    }
    identify_->setEnabled(canIdentify);
    identify_->setToolTip(emergency_.isLatched() ? emergency_.refusal() : QString());
    cancel_->setEnabled(running);
    progress_->setVisible(available);
}

void ModelPanel::showProgress() {
    if (!running_) {
        return;
    }
    const qint64 elapsed = clock_.elapsed();
    if (total_ > 0) {
        // The bar counts in thousandths: a budget of model runs may pass an int's range.
        progress_->setRange(0, 1000);
        progress_->setValue(static_cast<int>(1000 * done_ / total_));
    }
    QString text = total_ <= 0
                       ? tr("Identifying... %1 so far").arg(duration(elapsed))
                       : tr("Identifying: %1 of about %2 model runs · %3")
                             .arg(done_)
                             .arg(total_)
                             .arg(progressTime(
                                 elapsed, static_cast<int>(std::min<long long>(done_, 1000000000)),
                                 static_cast<int>(std::min<long long>(total_, 1000000000))));
    if (stoppedByEmergency_) {
        text = tr("E-STOP: cancelling. %1").arg(text);
    } else if (identification_->isCancelled()) {
        text = tr("Cancelling. %1").arg(text);
    }
    setTranslatedText(status_, [text] { return text; });
}

void ModelPanel::showResult(int id, std::shared_ptr<const sim::IdentificationResult> result) {
    if (id != requestId_) {
        return;  // an identification the operator has since replaced
    }
    const std::shared_ptr<const core::Demonstration> from = std::move(identifying_);
    setRunning(false);
    progress_->setRange(0, 1);
    progress_->setValue(result->ok() ? 1 : 0);
    const QString took = duration(clock_.elapsed());
    const bool hadModel = session_.identifiedModel() != nullptr;
    progress_->setTextVisible(true);
    if (result->cancelled) {
        progress_->setFormat(tr("Cancelled"));
        const bool byEmergency = stoppedByEmergency_;
        const bool dataChanged = from != session_.demonstration();
        showStatus(status_, tr("Model"), [took, byEmergency, dataChanged, hadModel] {
            const QString what = byEmergency   ? tr("Stopped by E-STOP after %1.").arg(took)
                                 : dataChanged ? tr("Cancelled after %1: the demonstration or "
                                                    "the car changed.")
                                                     .arg(took)
                                               : tr("Cancelled after %1.").arg(took);
            return QStringLiteral("%1 %2").arg(
                what,
                hadModel ? tr("The model identified before is kept.") : tr("No model was kept."));
        });
    } else if (!result->refusal.isEmpty()) {
        progress_->setFormat(tr("Refused"));
        const QString refusal = result->refusal;
        showStatus(
            status_, tr("Model"),
            [refusal] {
                return tr("This demonstration cannot identify the car: %1. Record one that "
                          "drives the car through a slide, with throttle and steering that "
                          "change.")
                    .arg(refusal);
            },
            MessageLevel::Warning);
    } else {
        try {
            session_.setIdentifiedModel(result, from);
            progress_->setFormat(tr("Done"));
            // The figures are the summary's, just below (and in the log with this line).
            logMessage(this, tr("Model"), MessageLevel::Info, summary_->text());
            showStatus(status_, tr("Model"), [took] {
                return tr("Identified in %1; mpc plans through the new model.").arg(took);
            });
        } catch (const std::invalid_argument& e) {
            const QString why = QString::fromStdString(e.what());
            showStatus(
                status_, tr("Model"),
                [why] { return tr("The model identified was not kept: %1.").arg(why); },
                MessageLevel::Warning);
        }
    }
    emit finished();
}

void ModelPanel::showModel() {
    const QString plant = session_.plant();
    const std::shared_ptr<const sim::IdentificationResult> model = session_.identifiedModel();
    const bool available = sim::identificationAvailable(plant);
    const QString plantName =
        QCoreApplication::translate("PlantCatalog", sim::PlantCatalog::get(plant).displayName);
    if (!available) {
        summary_->setText(tr("Only the slide-car can be identified: the %1 has no model to "
                             "identify here, and mpc does not run on it.")
                              .arg(plantName));
    } else if (!model) {
        summary_->setText(
            tr("No model yet. Identify fits the car's friction, grip, drive, "
               "steering and delays to the demonstration; until then a simulated "
               "run of mpc identifies one itself as it starts, and the rig waits for one."));
    } else {
        int fitted = 0, identified = 0;
        for (const sim::IdentifiedParameter& p : model->table) {
            fitted += p.fitted ? 1 : 0;
            identified += p.identified ? 1 : 0;
        }
        summary_->setText(tr("Model: pose error %1 cm RMS per segment over %2 segments (the "
                             "prior's %3 cm); %4 of %5 fitted parameters identified, the rest held "
                             "at their prior or, where the data reject it, undetermined. mpc "
                             "plans through this model.")
                              .arg(centimetres(model->positionRms))
                              .arg(model->segments.size())
                              .arg(centimetres(model->priorPositionRms))
                              .arg(identified)
                              .arg(fitted));
    }
    summary_->setStyleSheet(model ? QStringLiteral("QLabel { color: #1b5e20; }") : QString());

    // The table: every fitted parameter, its value, unit, deviation and verdict.
    table_->clearContents();
    table_->setRowCount(0);
    QStringList held;
    if (model) {
        for (const sim::IdentifiedParameter& p : model->table) {
            if (!p.fitted) {
                held << p.key;
                continue;
            }
            const int row = table_->rowCount();
            table_->insertRow(row);
            const QString verdict = p.identified      ? tr("identified")
                                    : p.heldAtPrior() ? tr("held")
                                                      : tr("undetermined");
            const QString deviation = std::isfinite(p.std) && p.std > 0.0
                                          ? QStringLiteral("± %1").arg(p.std, 0, 'g', 2)
                                          : QStringLiteral("—");
            const QStringList cells = {p.key, QString::number(p.value, 'g', 4), unitText(p.unit),
                                       deviation, verdict};
            for (int c = 0; c < cells.size(); ++c) {
                auto* item = new QTableWidgetItem(cells[c]);
                if (c == 1 || c == 3) {
                    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                }
                if (!p.identified) {
                    item->setForeground(QBrush(QColor(0x66, 0x66, 0x66)));
                }
                item->setToolTip(
                    p.identified
                        ? tr("%1: identified (prior %2)").arg(p.key).arg(p.prior, 0, 'g', 4)
                    : p.heldAtPrior()
                        ? tr("%1: the data did not determine it; held at its prior").arg(p.key)
                        : tr("%1: fitted, but the data did not determine it").arg(p.key));
                table_->setItem(row, c, item);
            }
        }
    }
    table_->setVisible(model != nullptr);
    held_->setVisible(model != nullptr);
    held_->setText(
        tr("Not fitted (measured, or the catalog's): %1").arg(held.join(QStringLiteral(", "))));

    // The figure: the recorded path, and the model's replay of the same actions from the same
    // start, open loop over the whole run.
    figure_ = plot::Figure();
    figure_.panels.resize(1);
    plot::Axes& axes = figure_.panels.front();
    axes.equalAspect = true;
    axes.xLabel = tr("x [m]");
    axes.yLabel = tr("y [m]");
    axes.emptyNote = tr("no path");
    const auto& pose = session_.profile().info.pose;
    const auto demonstration = session_.demonstration();
    if (pose && demonstration && available) {
        const auto path = [&pose](const Eigen::MatrixXd& states) {
            std::vector<QPointF> points;
            points.reserve(static_cast<size_t>(states.rows()));
            for (Eigen::Index k = 0; k < states.rows(); ++k) {
                points.emplace_back(states(k, pose->x), states(k, pose->y));
            }
            return points;
        };
        plot::Line recorded;
        recorded.label = tr("recorded");
        recorded.points = path(demonstration->states);
        recorded.color = QColor(0x1f, 0x77, 0xb4);
        recorded.width = 2.5;
        axes.lines.push_back(std::move(recorded));
        if (model) {
            plot::Line replay;
            replay.label = tr("model, replaying the recorded actions");
            replay.points =
                path(sim::replayRun(*demonstration, model->parameters, settings_.physicsSubsteps));
            replay.color = QColor(0xd6, 0x27, 0x28);
            replay.width = 2.0;
            replay.style = Qt::DashLine;
            axes.lines.push_back(std::move(replay));
        }
    }
    figureView_->setVisible(available);
    showFigure();
}

void ModelPanel::showFigure() {
    if (figure_.panels.empty() || !figureView_->isVisible() || figureView_->width() < 10) {
        return;
    }
    // As wide as the panel and as tall as the path needs at one scale on both axes (a parking
    // manoeuvre is long and flat), drawn at the size it is shown so its text stays readable.
    double aspect = 0.6;
    QRectF bounds;
    for (const plot::Line& line : figure_.panels.front().lines) {
        for (const QPointF& p : line.points) {
            bounds = bounds.isNull() ? QRectF(p, QSizeF(1e-9, 1e-9))
                                     : bounds.united(QRectF(p, QSizeF(1e-9, 1e-9)));
        }
    }
    if (bounds.width() > 0.0) {
        aspect = std::clamp(bounds.height() / bounds.width(), 0.35, 1.0);
    }
    const int width = figureView_->width();
    const int height =
        std::clamp(static_cast<int>(width * aspect) + 3 * fontMetrics().height(), 160, 480);
    if (figureView_->minimumHeight() != height) {
        figureView_->setMinimumHeight(height);
    }
    plot::Figure onScreen = figure_;
    onScreen.size = QSize(width, height);
    figureView_->setPixmap(QPixmap::fromImage(plot::renderFigure(onScreen)));
}

bool ModelPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == figureView_ && event->type() == QEvent::Resize) {
        const auto* resize = static_cast<QResizeEvent*>(event);
        if (resize->size().width() != resize->oldSize().width()) {
            QTimer::singleShot(0, this, &ModelPanel::showFigure);
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ModelPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void ModelPanel::retranslateUi() {
    intro_->setText(
        tr("Fits the car's physical parameters to the demonstration (as prisca-cli "
           "identify). mpc plans through the model; the session saves it."));
    identify_->setText(tr("Identify"));
    cancel_->setText(tr("Cancel"));
    table_->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Value"), tr("Unit"), tr("Std. dev."), tr("Verdict")});
    showModel();
}

}  // namespace prisca::app
