#include "app/workers/IdentificationWorker.h"

#include <QElapsedTimer>

#include <exception>
#include <stdexcept>

namespace prisca::app {

namespace {
// The search reports every few model runs; the bar needs a few updates a second, not hundreds.
constexpr qint64 kProgressIntervalMs = 150;
}  // namespace

void IdentificationWorker::run(const IdentificationRequest& request) {
    QElapsedTimer sinceReport;
    sinceReport.start();
    const int id = request.id;
    try {
        if (!request.demonstration) {
            throw std::invalid_argument("no demonstration to identify from");
        }
        if (cancelled_.load()) {  // cancelled before it began here
            auto cancelled = std::make_shared<sim::IdentificationResult>();
            cancelled->cancelled = true;
            cancelled->parameters = request.prior;
            emit finished(id, cancelled);
            return;
        }
        auto result = std::make_shared<const sim::IdentificationResult>(
            sim::identifyPlant({*request.demonstration}, request.prior, request.settings,
                               [&](long long done, long long total) {
                                   if (sinceReport.elapsed() >= kProgressIntervalMs) {
                                       sinceReport.restart();
                                       emit progress(id, done, total);
                                   }
                                   return !cancelled_.load();
                               }));
        emit finished(id, result);
    } catch (const std::exception& e) {
        emit failed(id, QString::fromStdString(e.what()));
    }
}

}  // namespace prisca::app
