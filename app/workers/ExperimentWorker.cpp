#include "app/workers/ExperimentWorker.h"

#include <QRegularExpression>

#include <exception>

namespace prisca::app {

void ExperimentWorker::run(const ExperimentRequest& request) {
    // The experiments report "k/N"; the bar follows it.
    const auto report = [this](const QString& text) {
        static const QRegularExpression fraction(QStringLiteral("(\\d+)/(\\d+)"));
        const QRegularExpressionMatch m = fraction.match(text);
        if (m.hasMatch()) {
            emit progress(m.captured(1).toInt(), m.captured(2).toInt(), text);
        } else {
            emit progress(0, 0, text);
        }
    };
    try {
        if (request.kind == ExperimentRequest::Kind::Table1) {
            sim::Table1Settings settings;
            settings.trials = request.trials;
            settings.run = request.settings;
            settings.keepPaths = true;  // for Fig. 7
            settings.cancelled = [this] { return cancelled_.load(); };
            settings.progress = report;
            auto result =
                std::make_shared<sim::Table1Result>(sim::runTable1(settings, request.task));
            emit table1Finished(result);
        } else {
            sim::LearningCurveSettings settings;
            settings.runs = request.runs;
            settings.budgetSteps = request.budgetSteps;
            settings.run = request.settings;
            settings.cancelled = [this] { return cancelled_.load(); };
            settings.progress = report;
            const auto curves = sim::runLearningCurves(settings, request.task);
            const core::Demonstration& demonstration = *request.task.demonstration;
            auto summaries = std::make_shared<std::vector<sim::CurveSummary>>(sim::summarizeCurves(
                curves, demonstration.length(), request.budgetSteps, demonstration.dt));
            emit curvesFinished(summaries, cancelled_.load());
        }
    } catch (const std::exception& e) {
        emit failed(QString::fromStdString(e.what()));
    }
}

}  // namespace prisca::app
