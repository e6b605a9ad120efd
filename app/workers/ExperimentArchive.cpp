#include "app/workers/ExperimentArchive.h"

#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "sim/MethodCatalog.h"

#include <QDataStream>
#include <QDir>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>

namespace prisca::app {

namespace {

// "PRXP" and the layout's version; a reader refuses any other.
constexpr quint32 kMagic = 0x50525850;
constexpr quint32 kVersion = 1;
// A Table I of 1000 trials with every figure path is about 30 MB.
constexpr qint64 kMaxBytes = qint64(128) << 20;
// A pose or value past this is a damaged file, not an experiment [m, s, ...].
constexpr double kMaxMagnitude = 1e9;

void put(QDataStream& out, const sim::TrialSummary& t) {
    out << t.finalPositionError << t.finalHeadingError << t.trackingRms << t.pathRms << t.meanCost
        << t.duration << t.controllerMicrosecondsPerStep << t.complete;
}

void get(QDataStream& in, sim::TrialSummary& t) {
    in >> t.finalPositionError >> t.finalHeadingError >> t.trackingRms >> t.pathRms >> t.meanCost >>
        t.duration >> t.controllerMicrosecondsPerStep >> t.complete;
}

template <typename T, typename Put>
void putVector(QDataStream& out, const std::vector<T>& values, Put putOne) {
    out << static_cast<quint32>(values.size());
    for (const T& v : values) {
        putOne(out, v);
    }
}

// False for a size no file of ours has (the stream is then marked corrupt): every element takes
// at least one byte, so a count past the bytes left is damage, and memory stays within a small
// multiple of the file's size.
template <typename T, typename Get>
bool getVector(QDataStream& in, std::vector<T>& values, Get getOne) {
    quint32 n = 0;
    in >> n;
    if (in.status() != QDataStream::Ok || n > in.device()->bytesAvailable()) {
        in.setStatus(QDataStream::ReadCorruptData);
        return false;
    }
    values.clear();
    values.reserve(std::min<quint32>(n, 100000));
    for (quint32 i = 0; i < n && in.status() == QDataStream::Ok; ++i) {
        T v{};
        getOne(in, v);
        values.push_back(std::move(v));
    }
    return in.status() == QDataStream::Ok;
}

void putDoubles(QDataStream& out, const std::vector<double>& v) {
    putVector(out, v, [](QDataStream& s, double x) { s << x; });
}
bool getDoubles(QDataStream& in, std::vector<double>& v) {
    return getVector(in, v, [](QDataStream& s, double& x) { s >> x; });
}

void putBand(QDataStream& out, const core::ConfidenceBand& b) {
    putDoubles(out, b.mean);
    putDoubles(out, b.lower);
    putDoubles(out, b.upper);
    putDoubles(out, b.standardDeviation);
    putVector(out, b.count, [](QDataStream& s, int x) { s << static_cast<qint32>(x); });
}
bool getBand(QDataStream& in, core::ConfidenceBand& b) {
    return getDoubles(in, b.mean) && getDoubles(in, b.lower) && getDoubles(in, b.upper) &&
           getDoubles(in, b.standardDeviation) &&
           getVector(in, b.count, [](QDataStream& s, int& x) {
               qint32 v = 0;
               s >> v;
               x = v;
           });
}

void putPose(QDataStream& s, const Eigen::Vector3d& p) {
    s << p[0] << p[1] << p[2];
}
void getPose(QDataStream& s, Eigen::Vector3d& p) {
    s >> p[0] >> p[1] >> p[2];
    if (!(p.array().abs() <= kMaxMagnitude).all()) {  // NaN too: a figure cannot draw it
        s.setStatus(QDataStream::ReadCorruptData);
    }
}

// A method this build knows, or the stream is marked corrupt.
void getMethod(QDataStream& s, QString& method) {
    s >> method;
    if (!sim::MethodCatalog::contains(method)) {
        s.setStatus(QDataStream::ReadCorruptData);
    }
}

// Finite or NaN (a point no run reached), never infinite or absurd.
bool plausible(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(),
                       [](double v) { return std::isnan(v) || std::abs(v) <= kMaxMagnitude; });
}

}  // namespace

QString keptExperimentPath() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("experiments/last.dat"));
}

bool saveKeptExperiment(const QString& path, const KeptExperiment& kept, QString* error) {
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(QDataStream::Qt_6_0);
    out.setFloatingPointPrecision(QDataStream::DoublePrecision);
    const ExperimentRecord& r = kept.record;
    out << kMagic << kVersion << r.curves << r.plant << r.poseTarget << static_cast<qint32>(r.count)
        << static_cast<qint32>(r.seed) << static_cast<qint64>(r.budget) << r.demonstration
        << r.finished;
    if (!r.curves) {
        if (!kept.table1) {
            *error = QStringLiteral("%1: no result to keep").arg(path);
            return false;
        }
        const sim::Table1Result& t = *kept.table1;
        const QStringList drawn = figures::parkingFigureMethods();
        putPose(out, t.lot);
        out << t.cancelled;
        putVector(out, t.methods, [&](QDataStream& s, const sim::MethodTrials& m) {
            s << m.method;
            putVector(s, m.trials, put);
            putVector(s, m.completed, [](QDataStream& s2, bool b) { s2 << b; });
            // Only the figure's methods' paths: the rest would be most of the file, unseen.
            const std::vector<std::vector<Eigen::Vector3d>> none;
            putVector(s, drawn.contains(m.method) ? m.paths : none,
                      [](QDataStream& s2, const std::vector<Eigen::Vector3d>& path) {
                          putVector(s2, path, putPose);
                      });
            putVector(s, m.training, put);
        });
    } else {
        if (!kept.curves) {
            *error = QStringLiteral("%1: no result to keep").arg(path);
            return false;
        }
        out << kept.curvesCancelled;
        putVector(out, *kept.curves, [](QDataStream& s, const sim::CurveSummary& c) {
            s << c.method;
            putVector(s, c.steps,
                      [](QDataStream& s2, long long x) { s2 << static_cast<qint64>(x); });
            putDoubles(s, c.seconds);
            putBand(s, c.band);
        });
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    core::FileError fileError;
    if (!core::writeFileAtomically(path, bytes, &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

std::optional<KeptExperiment> loadKeptExperiment(const QString& path, QString* error) {
    core::FileError fileError;
    const auto bytes = core::readFileBounded(path, kMaxBytes, &fileError);
    if (!bytes) {
        *error = fileError.toString();
        return std::nullopt;
    }
    QDataStream in(*bytes);
    in.setVersion(QDataStream::Qt_6_0);
    in.setFloatingPointPrecision(QDataStream::DoublePrecision);
    quint32 magic = 0, version = 0;
    in >> magic >> version;
    if (in.status() != QDataStream::Ok || magic != kMagic) {
        *error = QStringLiteral("%1: not a kept experiment").arg(path);
        return std::nullopt;
    }
    if (version != kVersion) {
        *error = QStringLiteral("%1: a kept experiment of version %2 (this build reads %3)")
                     .arg(path)
                     .arg(version)
                     .arg(kVersion);
        return std::nullopt;
    }
    KeptExperiment kept;
    ExperimentRecord& r = kept.record;
    qint32 count = 0, seed = 0;
    qint64 budget = 0;
    in >> r.curves >> r.plant >> r.poseTarget >> count >> seed >> budget >> r.demonstration >>
        r.finished;
    r.count = count;
    r.seed = seed;
    r.budget = budget;
    bool ok = in.status() == QDataStream::Ok;
    if (ok && !r.curves) {
        auto t = std::make_shared<sim::Table1Result>();
        getPose(in, t->lot);
        in >> t->cancelled;
        ok = getVector(in, t->methods, [](QDataStream& s, sim::MethodTrials& m) {
            getMethod(s, m.method);
            getVector(s, m.trials, get);
            getVector(s, m.completed, [](QDataStream& s2, bool& b) { s2 >> b; });
            getVector(s, m.paths, [](QDataStream& s2, std::vector<Eigen::Vector3d>& p) {
                getVector(s2, p, getPose);
            });
            getVector(s, m.training, get);
        });
        for (const sim::MethodTrials& m : t->methods) {
            ok = ok && m.completed.size() == m.trials.size() &&
                 (m.paths.empty() || m.paths.size() == m.trials.size());
        }
        kept.table1 = t;
    } else if (ok) {
        auto curves = std::make_shared<std::vector<sim::CurveSummary>>();
        in >> kept.curvesCancelled;
        ok = getVector(in, *curves, [](QDataStream& s, sim::CurveSummary& c) {
            getMethod(s, c.method);
            getVector(s, c.steps, [](QDataStream& s2, long long& x) {
                qint64 v = 0;
                s2 >> v;
                x = v;
            });
            getDoubles(s, c.seconds);
            getBand(s, c.band);
        });
        for (const sim::CurveSummary& c : *curves) {
            const size_t n = c.seconds.size();
            ok = ok && c.steps.size() == n && c.band.mean.size() == n && c.band.lower.size() == n &&
                 c.band.upper.size() == n && c.band.standardDeviation.size() == n &&
                 c.band.count.size() == n && plausible(c.seconds) && plausible(c.band.mean) &&
                 plausible(c.band.lower) && plausible(c.band.upper);
        }
        kept.curves = curves;
    }
    if (!ok || in.status() != QDataStream::Ok || !in.atEnd()) {
        *error = QStringLiteral("%1: a damaged kept experiment").arg(path);
        return std::nullopt;
    }
    return kept;
}

}  // namespace prisca::app
