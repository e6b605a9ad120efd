#include "sim/run/RunLogBuilder.h"

namespace prisca::sim {

core::RunLog startRunLog(const PlantInfo& info, const QString& method, double dt,
                         const core::Controller& controller) {
    core::RunLog log;
    log.plant = info.name;
    log.method = method;
    log.dt = dt;
    log.columns << QStringLiteral("trial") << QStringLiteral("t");
    log.units << QStringLiteral("1") << QStringLiteral("s");
    for (const QString& prefix : {QString(), QStringLiteral("obs_")}) {
        for (int i = 0; i < info.stateDimension(); ++i) {
            log.columns << prefix + info.stateNames[i];
            log.units << info.stateUnits[i];
        }
    }
    log.columns << QStringLiteral("ref_index");
    log.units << QStringLiteral("1");
    for (int i = 0; i < info.stateDimension(); ++i) {
        // A vehicle's pose error is in the desired pose's frame: say so in the column name.
        QString name = info.stateNames[i];
        if (info.pose) {
            name = i == info.pose->x         ? QStringLiteral("lon")
                   : i == info.pose->y       ? QStringLiteral("lat")
                   : i == info.pose->heading ? QStringLiteral("heading")
                                             : name;
        }
        log.columns << QStringLiteral("e_") + name;
        log.units << info.stateUnits[i];
    }
    for (const QString& prefix : {QStringLiteral("u_"), QStringLiteral("ustar_")}) {
        for (int l = 0; l < info.actionDimension(); ++l) {
            log.columns << prefix + info.actionNames[l];
            log.units << info.actionUnits[l];
        }
    }
    log.columns << QStringLiteral("cost");
    log.units << QStringLiteral("1");
    if (const Eigen::MatrixXd* theta = controller.learnedParameters()) {
        for (Eigen::Index l = 0; l < theta->cols(); ++l) {
            for (Eigen::Index i = 0; i < theta->rows(); ++i) {
                log.columns << QStringLiteral("theta_%1_%2").arg(i).arg(info.actionNames[l]);
                log.units << QStringLiteral("1");
            }
        }
    }
    log.rows.resize(0, log.columns.size());
    return log;
}

void appendRunLogTrial(core::RunLog& log, int trial, const EpisodeResult& result, double dt) {
    const Eigen::Index first = log.rows.rows();
    log.rows.conservativeResize(first + static_cast<Eigen::Index>(result.steps.size()),
                                log.columns.size());
    for (size_t k = 0; k < result.steps.size(); ++k) {
        const StepRecord& s = result.steps[k];
        Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(log.columns.size());
        Eigen::Index c = 0;
        row[c++] = trial;
        row[c++] = static_cast<double>(k) * dt;
        for (const Eigen::VectorXd* v : {&s.state, &s.observation}) {
            row.segment(c, v->size()) = v->transpose();
            c += v->size();
        }
        row[c++] = s.referenceIndex;
        for (const Eigen::VectorXd* v : {&s.deviation, &s.action, &s.referenceAction}) {
            row.segment(c, v->size()) = v->transpose();
            c += v->size();
        }
        row[c++] = s.cost;
        const Eigen::Index room = log.columns.size() - c;
        if (s.parameters.size() > 0 && s.parameters.size() <= room) {
            row.segment(c, s.parameters.size()) = s.parameters.transpose();
        }
        log.rows.row(first + static_cast<Eigen::Index>(k)) = row;
    }
}

}  // namespace prisca::sim
