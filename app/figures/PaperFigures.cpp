#include "app/figures/PaperFigures.h"

#include <QCoreApplication>

#include "core/Table1Report.h"
#include "sim/MethodCatalog.h"

#include <cmath>

namespace prisca::app::figures {

namespace {

// The car's outline at a pose, in centimetres.
plot::Shape carOutline(const Eigen::Vector3d& pose, double length, double width, QColor pen,
                       QColor brush, Qt::PenStyle style = Qt::SolidLine) {
    plot::Shape shape;
    const double c = std::cos(pose[2]), s = std::sin(pose[2]);
    // A pointed nose so the heading reads at a glance.
    for (const auto& [dx, dy] :
         {std::pair{0.5, 0.5}, {0.62, 0.0}, {0.5, -0.5}, {-0.5, -0.5}, {-0.5, 0.5}}) {
        const double x = dx * length, y = dy * width;
        shape.points.emplace_back(100.0 * (pose[0] + c * x - s * y),
                                  100.0 * (pose[1] + s * x + c * y));
    }
    shape.pen = pen;
    shape.brush = brush;
    shape.style = style;
    return shape;
}

}  // namespace

QStringList parkingFigureMethods() {
    return {QStringLiteral("playback"), QStringLiteral("pd"), QStringLiteral("prisca")};
}

plot::Figure parkingFigure(const sim::Table1Result& result, double carLength, double carWidth) {
    plot::Figure figure;
    figure.size = QSize(1500, 1000);
    figure.title = QCoreApplication::translate(
        "PaperFigures", "Slide parking: every trial's path and end posture (lot dashed red)");
    const QStringList shown = parkingFigureMethods();
    const QColor colours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e),
                              QColor(0x2c, 0xa0, 0x2c)};
    std::vector<plot::Axes> top, bottom;
    for (int i = 0; i < shown.size(); ++i) {
        const sim::MethodTrials* trials = nullptr;
        for (const sim::MethodTrials& m : result.methods) {
            if (m.method == shown[i])
                trials = &m;
        }
        if (!trials)
            continue;
        plot::Axes whole, close;
        whole.title = sim::MethodCatalog::get(shown[i]).label;
        close.title = sim::MethodCatalog::get(shown[i]).label +
                      QCoreApplication::translate("PaperFigures", ": close-up of the lot");
        for (plot::Axes* axes : {&whole, &close}) {
            axes->xLabel = QCoreApplication::translate("PaperFigures", "x [cm]");
            axes->yLabel = QCoreApplication::translate("PaperFigures", "y [cm]");
            axes->equalAspect = true;
            axes->legend = false;
        }
        QColor pale = colours[i];
        pale.setAlpha(70);
        for (size_t t = 0; t < trials->paths.size(); ++t) {
            if (!trials->completed[t] || trials->paths[t].empty())
                continue;
            plot::Line path;
            path.color = pale;
            path.width = 1.0;
            for (const Eigen::Vector3d& p : trials->paths[t]) {
                path.points.emplace_back(100.0 * p[0], 100.0 * p[1]);
            }
            const plot::Shape end = carOutline(trials->paths[t].back(), carLength, carWidth,
                                               colours[i].darker(150), Qt::transparent);
            whole.lines.push_back(path);
            close.lines.push_back(path);
            whole.shapes.push_back(end);
            close.shapes.push_back(end);
        }
        const plot::Shape lot = carOutline(result.lot, carLength * 1.25, carWidth * 1.5, Qt::red,
                                           Qt::transparent, Qt::DashLine);
        whole.shapes.push_back(lot);
        close.shapes.push_back(lot);
        const double cx = 100.0 * result.lot[0], cy = 100.0 * result.lot[1];
        close.range = QRectF(cx - 50.0, cy - 50.0, 100.0, 100.0);
        top.push_back(whole);
        bottom.push_back(close);
    }
    figure.columns = std::max<int>(1, static_cast<int>(top.size()));
    figure.panels = top;
    figure.panels.insert(figure.panels.end(), bottom.begin(), bottom.end());
    return figure;
}

plot::Figure learningCurveFigure(const std::vector<QString>& methods,
                                 const std::vector<std::vector<double>>& seconds,
                                 const std::vector<core::ConfidenceBand>& bands,
                                 const QString& yLabel) {
    plot::Figure figure;
    plot::Axes axes;
    axes.title = QCoreApplication::translate("PaperFigures", "Learning curves: mean and 95% band");
    axes.xLabel = QCoreApplication::translate("PaperFigures", "simulated experience [s]");
    axes.yLabel = yLabel;
    axes.logY = true;
    for (size_t m = 0; m < methods.size(); ++m) {
        plot::Line line;
        line.label = sim::MethodCatalog::get(methods[m]).label;
        line.width = 2.0;
        plot::Band band;
        band.label = line.label;
        for (size_t g = 0; g < seconds[m].size(); ++g) {
            line.points.emplace_back(seconds[m][g], bands[m].mean[g]);
            band.x.push_back(seconds[m][g]);
            band.lower.push_back(bands[m].lower[g]);
            band.upper.push_back(bands[m].upper[g]);
        }
        axes.bands.push_back(band);
        axes.lines.push_back(line);
    }
    figure.panels.push_back(axes);
    return figure;
}

plot::Figure lemma41Figure(const std::vector<core::Lemma41Cell>& grid, int maxHorizon,
                           int gammaSteps) {
    plot::Figure figure;
    figure.size = QSize(1000, 800);
    plot::Axes axes;
    axes.title =
        QCoreApplication::translate("PaperFigures", "Lemma 4.1: Var(D) over \u03c4' = 2H steps");
    axes.xLabel = QStringLiteral("\u03b3");
    axes.yLabel = QStringLiteral("H [steps]");
    plot::Heatmap map;
    map.columns = gammaSteps;
    map.rows = maxHorizon;
    const double dg = 1.0 / (gammaSteps - 1);
    map.extent = QRectF(-dg / 2, 0.5, 1.0 + dg, maxHorizon);
    for (const core::Lemma41Cell& cell : grid) {
        map.values.push_back(cell.variance);
    }
    map.threshold = 1.0;
    map.low = QColor(250, 250, 250);
    map.high = QColor(150, 150, 150);
    map.valueLabel = QStringLiteral("Var(D)");
    axes.heatmap = map;
    figure.panels.push_back(axes);
    return figure;
}

plot::Figure trajectoryFigure(const std::vector<QPointF>& desired,
                              const std::vector<TrajectoryPanel>& panels) {
    plot::Figure figure;
    figure.size = QSize(700 * static_cast<int>(std::max<size_t>(1, panels.size())), 700);
    figure.columns = static_cast<int>(std::max<size_t>(1, panels.size()));
    for (const TrajectoryPanel& panel : panels) {
        plot::Axes axes;
        const auto mean = [](const std::vector<double>& values) {
            double sum = 0.0;
            for (double v : values) {
                sum += v;
            }
            return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
        };
        axes.title = QCoreApplication::translate(
                         "PaperFigures", "%1: RMS %2 m in time, %3 m to the path (mean of %4)")
                         .arg(sim::MethodCatalog::get(panel.method).label)
                         .arg(mean(panel.rms), 0, 'f', 2)
                         .arg(mean(panel.pathRms), 0, 'f', 2)
                         .arg(panel.rms.size());
        axes.xLabel = QCoreApplication::translate("PaperFigures", "x [m]");
        axes.yLabel = QCoreApplication::translate("PaperFigures", "y [m]");
        axes.equalAspect = true;
        plot::Line target;
        target.label = QStringLiteral("desired");
        target.color = QColor(0x2c, 0xa0, 0x2c);
        target.width = 2.5;
        target.points = desired;
        for (size_t t = 0; t < panel.paths.size(); ++t) {
            plot::Line actual;
            actual.label = t == 0 ? QStringLiteral("actual") : QString();
            actual.color = QColor(0xd6, 0x27, 0x28, 150);
            actual.width = 1.2;
            actual.points = panel.paths[t];
            axes.lines.push_back(actual);
        }
        axes.lines.push_back(target);
        figure.panels.push_back(axes);
    }
    return figure;
}

}  // namespace prisca::app::figures
