#pragma once

#include "app/plot/Figure.h"
#include "core/Lemma41.h"
#include "core/Statistics.h"
#include "sim/experiments/LearningCurveExperiment.h"
#include "sim/experiments/Table1Experiment.h"

#include <vector>

/// The paper's figures built as plot::Figure data from experiment results; shared by the
/// command line (files) and the application (on screen).
namespace prisca::app::figures {

/// Fig. 7: the trajectories and end postures of action playback, PD and PRISCA (top: the whole
/// manoeuvre; bottom: a close-up of the lot), in centimetres. Methods missing from the result
/// are left out.
plot::Figure parkingFigure(const sim::Table1Result& result, double carLength, double carWidth);
/// The methods whose paths parkingFigure draws, in its column order.
QStringList parkingFigureMethods();

/// Fig. 3b: mean tracking error and 95% band per method against simulated time, log scale.
plot::Figure learningCurveFigure(const std::vector<QString>& methods,
                                 const std::vector<std::vector<double>>& seconds,
                                 const std::vector<core::ConfidenceBand>& bands,
                                 const QString& yLabel);

/// Fig. 2: where Var(D) < 1 on the (H, gamma) grid.
plot::Figure lemma41Figure(const std::vector<core::Lemma41Cell>& grid, int maxHorizon,
                           int gammaSteps);

/// One method's trials for trajectoryFigure.
struct TrajectoryPanel {
    QString method;
    std::vector<std::vector<QPointF>> paths;  ///< per trial, world x, y [m]
    std::vector<double> rms;                  ///< per trial, tracking RMS [m]
    std::vector<double> pathRms;              ///< per trial, RMS distance to the path [m]
};

/// Fig. 4: the desired path (green) and every trial's actual path (red), one panel per method,
/// with the mean tracking RMS (time-aligned, and distance to the path) in the title.
plot::Figure trajectoryFigure(const std::vector<QPointF>& desired,
                              const std::vector<TrajectoryPanel>& panels);

}  // namespace prisca::app::figures
