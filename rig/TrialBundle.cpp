#include "rig/TrialBundle.h"

#include "core/DemonstrationCsv.h"
#include "core/FileIo.h"
#include "sim/PlantCatalog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <algorithm>

#include <opencv2/imgcodecs.hpp>

#include <unistd.h>
#include <cmath>

namespace prisca::rig {

namespace {

constexpr char kFormat[] = "prisca-trial-bundle 1";

void appendNumber(QByteArray& row, double v) {
    row += ',';
    if (std::isfinite(v)) {
        core::appendCsvNumber(row, v);
    }
}

}  // namespace

TrialBundleWriter::~TrialBundleWriter() {
    flush();
    if (samples_) {
        std::fclose(samples_);
    }
}

bool TrialBundleWriter::open(const QString& folder, const QJsonObject& header,
                             const core::Demonstration& demonstration, QString* error) {
    QDir dir(folder);
    if (dir.exists() && !dir.isEmpty()) {
        *error = QStringLiteral("%1: a folder with files in it already; a bundle needs a new one")
                     .arg(folder);
        return false;
    }
    const bool created = !dir.exists();
    // A bundle that cannot be written leaves nothing behind (an empty folder reads as a writer
    // that stopped): what this call made goes again.
    const auto undo = [&] {
        if (samples_) {
            std::fclose(samples_);
            samples_ = nullptr;
        }
        if (created) {
            QDir(folder).removeRecursively();
        } else {
            for (const char* name : {"bundle.json", "demonstration.csv", "samples.csv"}) {
                QFile::remove(dir.filePath(QLatin1String(name)));
            }
            dir.rmdir(QStringLiteral("frames"));
        }
        folder_.clear();
        return false;
    };
    if (!QDir().mkpath(folder + QStringLiteral("/frames"))) {
        *error = QStringLiteral("%1: cannot create the folder").arg(folder);
        return undo();
    }
    folder_ = folder;
    header_ = header;
    header_.insert("format", QString::fromLatin1(kFormat));
    core::FileError fileError;
    if (!core::writeFileAtomically(dir.filePath("bundle.json"),
                                   QJsonDocument(header_).toJson(QJsonDocument::Indented),
                                   &fileError) ||
        !core::writeDemonstrationCsv(demonstration, dir.filePath("demonstration.csv"),
                                     &fileError)) {
        *error = fileError.toString();
        return undo();
    }
    samples_ = std::fopen(QFile::encodeName(dir.filePath("samples.csv")).constData(), "wb");
    if (!samples_) {
        *error = QStringLiteral("%1: cannot write samples.csv").arg(folder);
        return undo();
    }
    pending_ =
        "# prisca-trial-samples 1\n# t [s]; frame (-1: simulation); found; x, y [m], psi "
        "[rad]; s0.. the controller's observation; u0.. its command; failsafe\n";
    if (!flush()) {
        *error = QStringLiteral("%1: cannot write samples.csv (the disk full?)").arg(folder);
        return undo();
    }
    return true;
}

void TrialBundleWriter::append(const BundleSample& s) {
    QByteArray row;
    core::appendCsvNumber(row, s.t);
    row += ',' + QByteArray::number(s.frame) + ',' + (s.found ? '1' : '0');
    appendNumber(row, s.found ? s.x : NAN);
    appendNumber(row, s.found ? s.y : NAN);
    appendNumber(row, s.found ? s.psi : NAN);
    row += ",s";
    for (double v : s.state) {
        appendNumber(row, v);
    }
    row += ",u";
    for (double v : s.action) {
        appendNumber(row, v);
    }
    row += s.failsafe ? ",1\n" : ",0\n";
    pending_ += row;
    if (s.t - lastFlushT_ >= 1.0) {
        lastFlushT_ = s.t;
        flush();
    }
}

bool TrialBundleWriter::addFrame(long long frame, const cv::Mat& image) {
    if (folder_.isEmpty() || image.empty()) {
        return false;
    }
    const QString path =
        QStringLiteral("%1/frames/%2.jpg").arg(folder_).arg(frame, 6, 10, QLatin1Char('0'));
    std::vector<uchar> bytes;
    if (!cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, 85})) {
        return false;
    }
    core::FileError error;
    return core::writeFileAtomically(
        path, QByteArray(reinterpret_cast<const char*>(bytes.data()), int(bytes.size())), &error);
}

bool TrialBundleWriter::flush() {
    if (!samples_ || pending_.isEmpty()) {
        return samples_ != nullptr;
    }
    const bool ok = std::fwrite(pending_.constData(), 1, size_t(pending_.size()), samples_) ==
                        size_t(pending_.size()) &&
                    std::fflush(samples_) == 0;
    ::fdatasync(fileno(samples_));
    pending_.clear();
    return ok;
}

bool TrialBundleWriter::finish(const QJsonObject& result, QString* error) {
    flush();
    header_.insert("result", result);
    core::FileError fileError;
    if (!core::writeFileAtomically(QDir(folder_).filePath("bundle.json"),
                                   QJsonDocument(header_).toJson(QJsonDocument::Indented),
                                   &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

QString TrialBundle::frameAt(size_t sample) const {
    if (sample >= samples.size() || frames.empty()) {
        return {};
    }
    const long long want = samples[sample].frame;
    // frames is in order: the first at or after `want`, or the one before it, whichever is nearer.
    const auto after = std::lower_bound(
        frames.begin(), frames.end(), want,
        [](const std::pair<long long, QString>& f, long long index) { return f.first < index; });
    if (after == frames.begin()) {
        return after->second;
    }
    const auto before = std::prev(after);
    if (after == frames.end() || want - before->first <= after->first - want) {
        return before->second;
    }
    return after->second;
}

std::optional<TrialBundle> TrialBundle::load(const QString& folder, QString* error) {
    TrialBundle b;
    b.folder = folder;
    const QDir dir(folder);
    if (!QFileInfo(folder).isDir()) {
        *error = QStringLiteral("%1: not a trial bundle (no such folder)").arg(folder);
        return std::nullopt;
    }
    // A bundle's files are its own: a link could lead anywhere (and an error would quote it).
    for (const char* name : {"bundle.json", "demonstration.csv", "samples.csv", "frames"}) {
        if (QFileInfo(dir.filePath(QLatin1String(name))).isSymLink()) {
            *error = QStringLiteral("%1/%2: a symbolic link; a trial bundle holds its own files")
                         .arg(folder, QLatin1String(name));
            return std::nullopt;
        }
    }
    core::FileError fileError;
    const auto json = core::readFileBounded(dir.filePath("bundle.json"), 16 << 20, &fileError);
    if (!json) {
        *error = fileError.toString();
        return std::nullopt;
    }
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(*json, &parse);
    if (!doc.isObject() || doc.object().value("format").toString() != QLatin1String(kFormat)) {
        *error = QStringLiteral("%1/bundle.json: not a trial bundle's (format \"%2\" expected)")
                     .arg(folder, QString::fromLatin1(kFormat));
        return std::nullopt;
    }
    b.header = doc.object();
    // The plant it ran on, which says how to read the rest (older bundles: the slide-car).
    const QString plant = b.header.value("plant").toString(QStringLiteral("slidecar"));
    const sim::PlantEntry* entry = sim::PlantCatalog::find(plant);
    if (!entry) {
        *error = QStringLiteral("%1/bundle.json: plant '%2' is not one this build knows (%3)")
                     .arg(folder, plant, sim::PlantCatalog::names().join(QStringLiteral(", ")));
        return std::nullopt;
    }
    const sim::PlantInfo info = entry->describe();
    auto demo = core::readDemonstrationCsv(dir.filePath("demonstration.csv"), &fileError);
    if (!demo) {
        *error = fileError.toString();
        return std::nullopt;
    }
    const int needed =
        info.pose ? 1 + std::max({info.pose->x, info.pose->y, info.pose->heading}) : 1;
    if (demo->length() == 0 || demo->states.cols() < needed) {
        *error = QStringLiteral(
                     "%1/demonstration.csv: %2 samples of %3 state columns; a %4 "
                     "trial's demonstration has samples of at least %5")
                     .arg(folder)
                     .arg(demo->length())
                     .arg(demo->states.cols())
                     .arg(plant)
                     .arg(needed);
        return std::nullopt;
    }
    b.demonstration = std::make_shared<core::Demonstration>(std::move(*demo));
    const auto csv =
        core::readFileBounded(dir.filePath("samples.csv"), qint64(1) << 30, &fileError);
    if (!csv) {
        *error = fileError.toString();
        return std::nullopt;
    }
    // Up to the last complete line: a writer killed mid-line leaves a partial one.
    const int end = csv->lastIndexOf('\n');
    const QList<QByteArray> lines = csv->left(end < 0 ? 0 : end).split('\n');
    for (int i = 0; i < lines.size(); ++i) {
        const QByteArray& line = lines[i];
        if (line.isEmpty() || line.startsWith('#')) {
            continue;
        }
        const QList<QByteArray> f = line.split(',');
        const int s = f.indexOf("s"), u = f.indexOf("u");
        if (f.size() < 8 || s != 6 || u < s) {
            *error = QStringLiteral("%1/samples.csv:%2: not a sample line").arg(folder).arg(i + 1);
            return std::nullopt;
        }
        BundleSample sample;
        const auto bad = [&](const QString& why) {
            *error = QStringLiteral("%1/samples.csv:%2: %3").arg(folder).arg(i + 1).arg(why);
            return std::nullopt;
        };
        bool okT = false;
        sample.t = f[0].toDouble(&okT);
        // A trial's time: within a day of its start (a 300-digit or non-finite time is no time).
        if (!okT || !std::isfinite(sample.t) || std::abs(sample.t) > 86400.0) {
            return bad(QStringLiteral("the time '%1' is not a trial's time in seconds")
                           .arg(QString::fromLatin1(f[0].left(40))));
        }
        sample.frame = f[1].toLongLong();
        sample.found = f[2] == "1";
        if (sample.found) {
            // A pose found is a pose on the floor: numbers, within 10 km of the origin.
            bool okX = false, okY = false, okPsi = false;
            sample.x = f[3].toDouble(&okX);
            sample.y = f[4].toDouble(&okY);
            sample.psi = f[5].toDouble(&okPsi);
            if (!okX || !okY || !okPsi || !std::isfinite(sample.x) || !std::isfinite(sample.y) ||
                !std::isfinite(sample.psi) || std::abs(sample.x) > 1e4 ||
                std::abs(sample.y) > 1e4) {
                return bad(QStringLiteral("a found pose (%1, %2, %3) is not a floor pose (x, y "
                                          "within 10 km, a finite heading)")
                               .arg(QString::fromLatin1(f[3].left(24)),
                                    QString::fromLatin1(f[4].left(24)),
                                    QString::fromLatin1(f[5].left(24))));
            }
        } else {
            sample.x = sample.y = sample.psi = NAN;
        }
        for (int k = s + 1; k < u; ++k) {
            sample.state.push_back(f[k].isEmpty() ? NAN : f[k].toDouble());
        }
        for (int k = u + 1; k < f.size() - 1; ++k) {
            sample.action.push_back(f[k].isEmpty() ? NAN : f[k].toDouble());
        }
        sample.failsafe = f.last() == "1";
        b.samples.push_back(std::move(sample));
    }
    for (const QString& name :
         QDir(dir.filePath("frames"))
             .entryList({"*.jpg"}, QDir::Files | QDir::NoSymLinks, QDir::Name)) {
        b.frames.emplace_back(QFileInfo(name).baseName().toLongLong(),
                              dir.filePath("frames/" + name));
    }
    return b;
}

bool writeSimulationBundle(const QString& folder, QJsonObject header, const sim::PlantInfo& info,
                           const core::Demonstration& demonstration,
                           const sim::EpisodeResult& result, const sim::TrialSummary& summary,
                           QString* error) {
    header.insert("kind", QStringLiteral("simulation"));
    header.insert("plant", info.name);
    TrialBundleWriter writer;
    if (!writer.open(folder, header, demonstration, error)) {
        return false;
    }
    for (const sim::StepRecord& step : result.steps) {
        BundleSample sample;
        sample.t = step.time;
        if (info.pose) {
            sample.x = step.state[info.pose->x];
            sample.y = step.state[info.pose->y];
            sample.psi = step.state[info.pose->heading];
        }
        // A pose that left the numbers (a diverged trial) is no pose found.
        sample.found = info.pose.has_value() && std::isfinite(sample.x) &&
                       std::isfinite(sample.y) && std::isfinite(sample.psi);
        sample.state.assign(step.observation.data(),
                            step.observation.data() + step.observation.size());
        sample.action.assign(step.action.data(), step.action.data() + step.action.size());
        writer.append(sample);
    }
    if (info.pose && result.finalState.size() > 2) {  // where the trial ended
        BundleSample end;
        end.t = summary.duration;
        end.x = result.finalState[info.pose->x];
        end.y = result.finalState[info.pose->y];
        end.psi = result.finalState[info.pose->heading];
        end.found = std::isfinite(end.x) && std::isfinite(end.y) && std::isfinite(end.psi);
        writer.append(end);
    }
    QJsonObject r{{"failsafe", result.lostTrack},
                  {"reason", result.lostTrack ? QStringLiteral("the robot left the demonstration")
                                              : QString()},
                  {"stopped", !summary.complete},
                  {"seconds", summary.duration}};
    if (info.pose) {
        r.insert("finalPositionErrorCm", summary.finalPositionError * 100.0);
        r.insert("finalHeadingErrorDeg", summary.finalHeadingError * 180.0 / M_PI);
    }
    return writer.finish(r, error);
}

QJsonObject summarizeBundle(const TrialBundle& bundle) {
    QJsonObject o{{"folder", bundle.folder},
                  {"kind", bundle.header.value("kind")},
                  {"method", bundle.header.value("method")},
                  {"complete", bundle.complete()},
                  {"samples", static_cast<double>(bundle.samples.size())},
                  {"frames", static_cast<double>(bundle.frames.size())}};
    int found = 0, failsafe = 0;
    const BundleSample* last = nullptr;
    for (const BundleSample& s : bundle.samples) {
        found += s.found;
        failsafe += s.failsafe;
        if (s.found) {
            last = &s;
        }
    }
    o.insert("seconds", bundle.samples.empty() ? 0.0 : bundle.samples.back().t);
    o.insert("samplesWithPose", found);
    o.insert("samplesInFailsafe", failsafe);
    const core::Demonstration& d = *bundle.demonstration;
    if (last && d.length() > 0 && d.states.cols() >= 3) {
        const Eigen::VectorXd lot = d.states.row(d.length() - 1).transpose();
        o.insert("finalPositionErrorCm", 100.0 * std::hypot(last->x - lot[0], last->y - lot[1]));
        o.insert("finalHeadingErrorDeg",
                 180.0 / M_PI * std::abs(std::remainder(last->psi - lot[2], 2.0 * M_PI)));
    }
    if (bundle.complete()) {
        o.insert("result", bundle.header.value("result"));
    }
    return o;
}

std::vector<core::Demonstration> recordedRuns(const TrialBundle& bundle) {
    std::vector<core::Demonstration> runs;
    if (!bundle.demonstration || bundle.samples.size() < 2) {
        return runs;
    }
    const core::Demonstration& demonstration = *bundle.demonstration;
    const size_t n = static_cast<size_t>(demonstration.stateDimension());
    const size_t m = static_cast<size_t>(demonstration.actionDimension());
    std::vector<double> spacing;
    for (size_t i = 1; i < bundle.samples.size(); ++i) {
        spacing.push_back(bundle.samples[i].t - bundle.samples[i - 1].t);
    }
    std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
    const double dt = spacing[spacing.size() / 2];
    if (!(dt > 0.0)) {
        return runs;
    }
    std::vector<const BundleSample*> part;
    auto flush = [&] {
        if (part.size() >= 10) {
            core::Demonstration run;
            run.plant = demonstration.plant;
            run.dt = dt;
            run.stateNames = demonstration.stateNames;
            run.stateUnits = demonstration.stateUnits;
            run.actionNames = demonstration.actionNames;
            run.actionUnits = demonstration.actionUnits;
            const int length = static_cast<int>(part.size());
            run.time.resize(length);
            run.states.resize(length, static_cast<int>(n));
            run.actions.resize(length, static_cast<int>(m));
            for (int k = 0; k < length; ++k) {
                run.time[k] = part[static_cast<size_t>(k)]->t;
                for (size_t j = 0; j < n; ++j) {
                    run.states(k, static_cast<int>(j)) = part[static_cast<size_t>(k)]->state[j];
                }
                for (size_t j = 0; j < m; ++j) {
                    run.actions(k, static_cast<int>(j)) = part[static_cast<size_t>(k)]->action[j];
                }
            }
            run.metadata.insert(QStringLiteral("source"), QStringLiteral("%1 (from t = %2 s)")
                                                              .arg(bundle.folder)
                                                              .arg(run.time[0], 0, 'f', 2));
            runs.push_back(std::move(run));
        }
        part.clear();
    };
    for (const BundleSample& sample : bundle.samples) {
        const bool usable = sample.found && !sample.failsafe && sample.state.size() == n &&
                            sample.action.size() == m;
        if (!usable || (!part.empty() && sample.t - part.back()->t > 1.5 * dt)) {
            flush();
        }
        if (usable) {
            part.push_back(&sample);
        }
    }
    flush();
    return runs;
}

}  // namespace prisca::rig
