#include "app/ExperimentWorker.h"

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
            settings.plant = request.plant;
            settings.trials = request.trials;
            settings.seed = request.seed;
            settings.threads = request.threads;
            settings.keepPaths = true;  // for Fig. 7
            settings.cancelled = [this] { return cancelled_.load(); };
            settings.progress = report;
            auto result = std::make_shared<sim::Table1Result>(
                sim::runTable1(settings, request.demonstration, request.profile, request.fittedB));
            emit table1Finished(result);
        } else {
            sim::LearningCurveSettings settings;
            settings.plant = request.plant;
            settings.runs = request.trials;
            settings.seed = request.seed;
            settings.budgetSteps = request.budgetSteps;
            settings.threads = request.threads;
            settings.cancelled = [this] { return cancelled_.load(); };
            settings.progress = report;
            const auto curves = sim::runLearningCurves(settings, request.demonstration,
                                                       request.profile, request.fittedB);
            auto summaries = std::make_shared<std::vector<sim::CurveSummary>>(
                sim::summarizeCurves(curves, request.demonstration->length(), request.budgetSteps,
                                     request.demonstration->dt));
            emit curvesFinished(summaries, cancelled_.load());
        }
    } catch (const std::exception& e) {
        emit failed(QString::fromStdString(e.what()));
    }
}

}  // namespace prisca::app
