// LabSession: the session file (JSON, versioned; every value checked as it is read).
#include "app/LabSession.h"
#include "app/LabSession_p.h"

#include "core/DemonstrationCsv.h"
#include "core/FileIo.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/planning/IdentificationReport.h"
#include "sim/run/Task.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::app {

namespace {

// 2: the slide-car's PRISCA starts from the PD+H+LSD law and learns through the closed loop;
// PRISCA's, the PD's and ILC's parameters were re-tuned with it, so those of a version-1 session
// are not applied (they would make the new form run away: development cells 3.83 -> 6.01 cm).
// 3: method parameters as the catalog declares them ("parameters": {"prisca.H": "10", ...});
// 2 and 1 kept them in per-method objects, still read.
constexpr int kSessionVersion = 4;

QJsonArray vectorToJson(const Eigen::VectorXd& v) {
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        a.append(v[i]);
    }
    return a;
}

// Reads a number from `object[key]`, or explains what is wrong with it.
bool readNumber(const QJsonObject& object, const QString& key, double low, double high,
                double* value, QString* error) {
    if (!object.contains(key)) {
        return true;  // keep the default
    }
    const QJsonValue v = object.value(key);
    if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < low ||
        v.toDouble() > high) {
        *error = LabSession::tr("'%1' must be a number from %2 to %3").arg(key).arg(low).arg(high);
        return false;
    }
    *value = v.toDouble();
    return true;
}

bool readInteger(const QJsonObject& object, const QString& key, int low, int high, int* value,
                 QString* error) {
    double d = *value;
    if (!readNumber(object, key, low, high, &d, error)) {
        return false;
    }
    if (d != std::floor(d)) {
        *error = LabSession::tr("'%1' must be a whole number").arg(key);
        return false;
    }
    *value = static_cast<int>(d);
    return true;
}

QJsonArray scalesToJson(const core::FeatureMap& features) {
    QJsonArray channels;
    for (const auto& channel : features.terms()) {
        QJsonArray scales;
        for (const core::FeatureTerm& term : channel) {
            scales.append(term.scale);
        }
        channels.append(scales);
    }
    return channels;
}

// Reads the scales of `features` from object[key] (same shape), or explains what is wrong.
bool readScales(const QJsonObject& object, const QString& key, core::FeatureMap* features,
                QString* error) {
    if (!object.contains(key)) {
        return true;
    }
    std::vector<std::vector<core::FeatureTerm>> terms = features->terms();
    const QJsonArray channels = object.value(key).toArray();
    if (channels.size() != static_cast<int>(terms.size())) {
        *error = LabSession::tr("'%1' must have %2 lists of scales").arg(key).arg(terms.size());
        return false;
    }
    for (int l = 0; l < channels.size(); ++l) {
        const QJsonArray scales = channels[l].toArray();
        if (scales.size() != static_cast<int>(terms[l].size())) {
            *error = LabSession::tr("'%1' list %2 must have %3 scales")
                         .arg(key)
                         .arg(l + 1)
                         .arg(terms[l].size());
            return false;
        }
        for (int j = 0; j < scales.size(); ++j) {
            if (!scales[j].isDouble() || !std::isfinite(scales[j].toDouble())) {
                *error = LabSession::tr("'%1' list %2 entry %3 must be a number")
                             .arg(key)
                             .arg(l + 1)
                             .arg(j + 1);
                return false;
            }
            terms[l][j].scale = scales[j].toDouble();
        }
    }
    *features = core::FeatureMap(terms);
    return true;
}

}  // namespace

using session::scripted;

QByteArray LabSession::toJson() const {
    QJsonObject fit{
        {"latency", fitOptions_.latency},
        {"responseSteps", fitOptions_.responseSteps},
        {"target", fitOptions_.target == core::ActionMappingFitOptions::Target::StateChange
                       ? "state"
                       : "rate"},
        {"nonNegative", fitOptions_.nonNegative},
        {"robust", fitOptions_.robust}};
    // Every parameter a method declares, by name, as `--param` writes it.
    QJsonObject parameters;
    for (const sim::MethodParameter* parameter : sim::MethodCatalog::parameters()) {
        parameters.insert(QString::fromLatin1(parameter->name),
                          parameter->format(parameter->value(task_.profile)));
    }
    QJsonObject root{
        {"format", "prisca-session"},
        {"version", kSessionVersion},
        {"plant", task_.plant},
        {"demonstration", demonstrationSource_},
        {"scriptedStyle", scriptedStyle_},
        {"scriptedSeed", static_cast<double>(scriptedSeed_)},
        {"mapping", task_.profile.mapping.toString()},
        {"fit", fit},
        {"method", method_},
        {"parameters", parameters},
        {"featureScales", scalesToJson(task_.profile.features)},
        {"limits", QJsonObject{{"lower", vectorToJson(task_.profile.info.actionLower)},
                               {"upper", vectorToJson(task_.profile.info.actionUpper)}}}};
    if (task_.profile.priscaFeatures) {
        root.insert("priscaFeatureScales", scalesToJson(*task_.profile.priscaFeatures));
    }
    if (task_.plantParameters) {
        // The plant file's values themselves, so the session holds the car even when the file
        // moves; its path names where they came from.
        root.insert(
            "plantParameters",
            QJsonObject{
                {"source", task_.plantParameters->source},
                {"file", QJsonDocument::fromJson(sim::plantParametersJson(*task_.plantParameters))
                             .object()}});
    }
    if (model_) {
        // The identified plant file as `prisca-cli identify` writes it, and the length of the
        // demonstration it came from (a file that changed since is not its data any more).
        const QString from = demonstrationSource_.isEmpty()
                                 ? QStringLiteral("the scripted operator (%1, seed %2)")
                                       .arg(scriptedStyle_)
                                       .arg(scriptedSeed_)
                                 : demonstrationSource_;
        root.insert(
            "model",
            QJsonObject{
                {"samples", static_cast<int>(task_.demonstration->length())},
                {"file", QJsonDocument::fromJson(
                             sim::identifiedPlantFile(
                                 *model_, QStringLiteral("identified from %1").arg(from), {from}))
                             .object()}});
    }
    if (!messages_.isEmpty()) {
        root.insert("messages", messages_);
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool LabSession::save(const QString& path, QString* error) const {
    core::FileError fileError;
    if (!core::writeFileAtomically(path, toJson(), &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

bool LabSession::open(const QString& path, QString* error) {
    core::FileError fileError;
    const std::optional<QByteArray> json =
        core::readFileBounded(path, kMaxSessionBytes, &fileError);
    if (!json) {
        *error = fileError.toString();
        return false;
    }
    return fromJson(*json, path, error);
}

bool LabSession::fromJson(const QByteArray& json, const QString& origin, QString* error) {
    const auto fail = [&](const QString& what) {
        *error = core::printable(tr("%1: %2").arg(origin, what));
        return false;
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        return fail(tr("not valid JSON at byte %1 (%2)")
                        .arg(parseError.offset)
                        .arg(parseError.errorString()));
    }
    const QJsonObject root = document.object();
    if (root.value("format").toString() != QLatin1String("prisca-session")) {
        return fail(tr("not a PRISCA Lab session (no \"format\": \"prisca-session\")"));
    }
    if (root.value("version").toInt(-1) > kSessionVersion) {
        return fail(tr("written by a newer PRISCA Lab (session version %1)")
                        .arg(root.value("version").toInt()));
    }
    const QString plant = root.value("plant").toString();
    if (!sim::PlantCatalog::names().contains(plant)) {
        return fail(tr("'plant' must be one of %1").arg(sim::PlantCatalog::names().join(", ")));
    }
    sim::MethodTuning profile = sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant));
    QString what;
    if (root.contains("mapping")) {
        const auto mapping = core::IntuitiveMapping::parse(root.value("mapping").toString(), &what);
        if (!mapping) {
            return fail(tr("'mapping': %1").arg(what));
        }
        if (mapping->signs.rows() != profile.mapping.signs.rows() ||
            mapping->signs.cols() != profile.mapping.signs.cols()) {
            return fail(tr("'mapping' must have %1 rows of %2 signs for the %3")
                            .arg(profile.mapping.signs.rows())
                            .arg(profile.mapping.signs.cols())
                            .arg(plant));
        }
        profile.mapping = *mapping;
    }
    const QString method = root.value("method").toString(QStringLiteral("prisca"));
    if (!sim::MethodCatalog::contains(method)) {
        return fail(tr("'method' must be one of %1").arg(sim::MethodCatalog::ids().join(", ")));
    }
    core::ActionMappingFitOptions fitOptions;
    const QJsonObject fit = root.value("fit").toObject();
    const QJsonObject pgsd = root.value("pgsd").toObject();
    // An earlier version's PRISCA, PD and ILC parameters were tuned for an earlier PRISCA: today's
    // defaults stand in for them (the operator is told), everything else is read as saved.
    const bool earlier = root.value("version").toInt(kSessionVersion) < 2;
    const QJsonObject prisca = earlier ? QJsonObject() : root.value("prisca").toObject();
    const QJsonObject pd = earlier ? QJsonObject() : root.value("pd").toObject();
    const QJsonObject ilc = earlier ? QJsonObject() : root.value("ilc").toObject();
    const bool ok = readInteger(fit, "latency", 0, 1000, &fitOptions.latency, &what) &&
                    readInteger(fit, "responseSteps", 1, 1000, &fitOptions.responseSteps, &what);
    if (!ok) {
        return fail(what);
    }
    // Every method parameter goes through its declaration, whichever version wrote it, so a
    // session holds only values today's checks accept.
    const auto apply = [&](const QString& name, const QString& value, const QString& key) {
        try {
            sim::MethodCatalog::setParameter(profile, name + QLatin1Char('=') + value);
        } catch (const std::invalid_argument& e) {
            what = tr("'%1': %2").arg(key, QString::fromUtf8(e.what()));
            return false;
        }
        return true;
    };
    // Versions 1 and 2 kept them in per-method objects, under names of their own.
    struct Legacy {
        const QJsonObject& object;
        const char* objectName;
        const char* key;
        const char* parameter;
    };
    const QJsonObject rootParameters{{"matchingWindow", root.value("matchingWindow")}};
    const Legacy legacy[] = {
        {rootParameters, "", "matchingWindow", "matching.window"},
        {prisca, "prisca", "horizon", "prisca.H"},
        {prisca, "prisca", "gamma", "prisca.gamma"},
        {prisca, "prisca", "beta", "prisca.beta"},
        {prisca, "prisca", "stepScale", "prisca.alpha0"},
        {prisca, "prisca", "thetaBound", "prisca.theta-bound"},
        {prisca, "prisca", "fromPd", "prisca.from-pd"},
        {prisca, "prisca", "automatic", "prisca.automatic"},
        {prisca, "prisca", "gradient", "prisca.gradient"},
        {prisca, "prisca", "effortWeight", "prisca.effort"},
        {prisca, "prisca", "useBaseline", "prisca.baseline"},
        {prisca, "prisca", "useInverseDepreciation", "prisca.depreciation"},
        {pgsd, "pgsd", "horizon", "pgsd.H"},
        {pgsd, "pgsd", "stepSize", "pgsd.alpha"},
        {pgsd, "pgsd", "thetaBound", "pgsd.theta-bound"},
        {pd, "pd", "kp", "pd.kp"},
        {pd, "pd", "kd", "pd.kd"},
        {pd, "pd", "horizon", "pd.H"},
        {ilc, "ilc", "learningScale", "ilc.learning"},
        {ilc, "ilc", "lead", "ilc.lead"},
        {ilc, "ilc", "cutoff", "ilc.cutoff"},
        {ilc, "ilc", "feedbackScale", "ilc.feedback"},
    };
    for (const Legacy& entry : legacy) {
        const QJsonValue value = entry.object.value(QLatin1String(entry.key));
        if (value.isUndefined() || value.isNull()) {
            continue;
        }
        QString text;
        if (value.isBool()) {
            text = value.toBool() ? QStringLiteral("on") : QStringLiteral("off");
        } else if (value.isDouble()) {
            text = QString::number(value.toDouble(), 'g', 17);
        } else if (value.isString()) {
            text = value.toString();
        } else if (value.isArray()) {
            QStringList numbers;
            for (const QJsonValue& v : value.toArray()) {
                numbers << (v.isDouble() ? QString::number(v.toDouble(), 'g', 17) : QString());
            }
            text = numbers.join(QLatin1Char(','));
        }
        const QString key = *entry.objectName
                                ? QStringLiteral("%1.%2").arg(QLatin1String(entry.objectName),
                                                              QLatin1String(entry.key))
                                : QString::fromLatin1(entry.key);
        if (!apply(QString::fromLatin1(entry.parameter), text, key)) {
            return fail(what);
        }
    }
    // Version 3 on: every declared parameter by name, as --param spells it.
    const QJsonValue parametersValue = root.value("parameters");
    if (!parametersValue.isUndefined() && !parametersValue.isObject()) {
        return fail(tr("'parameters' must be an object of \"name\": \"value\""));
    }
    const QJsonObject parameters = parametersValue.toObject();
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        if (!it.value().isString()) {
            return fail(
                tr("'parameters.%1' must be a string such as \"10\" or \"1,1.2\"").arg(it.key()));
        }
        if (!apply(it.key(), it.value().toString(), QStringLiteral("parameters"))) {
            return fail(what);
        }
    }
    if (!readScales(root, "featureScales", &profile.features, &what)) {
        return fail(what);
    }
    if (profile.priscaFeatures && !earlier &&
        !readScales(root, "priscaFeatureScales", &*profile.priscaFeatures, &what)) {
        return fail(what);
    }
    if (root.contains("limits")) {
        const QJsonObject limits = root.value("limits").toObject();
        const sim::PlantInfo physical = sim::PlantCatalog::describe(plant);
        const Eigen::Index m = physical.actionLower.size();
        Eigen::VectorXd lower = physical.actionLower, upper = physical.actionUpper;
        const auto readLimits = [&](const char* key, Eigen::VectorXd* out) {
            const QJsonArray a = limits.value(key).toArray();
            if (a.size() != m) {
                what = tr("'limits.%1' must be a list of %2 numbers").arg(key).arg(m);
                return false;
            }
            for (int l = 0; l < m; ++l) {
                (*out)[l] = a[l].toDouble(std::numeric_limits<double>::quiet_NaN());
            }
            return true;
        };
        if (!readLimits("lower", &lower) || !readLimits("upper", &upper)) {
            return fail(what);
        }
        for (Eigen::Index l = 0; l < m; ++l) {
            if (!(lower[l] < upper[l]) || lower[l] < physical.actionLower[l] ||
                upper[l] > physical.actionUpper[l]) {
                return fail(tr("'limits' of %1 must have lower < upper within [%2, %3]")
                                .arg(physical.actionNames[l])
                                .arg(physical.actionLower[l])
                                .arg(physical.actionUpper[l]));
            }
        }
        profile.info.actionLower = lower;
        profile.info.actionUpper = upper;
    }
    fitOptions.target = fit.value("target").toString() == QLatin1String("state")
                            ? core::ActionMappingFitOptions::Target::StateChange
                            : core::ActionMappingFitOptions::Target::RateChange;
    fitOptions.nonNegative = fit.value("nonNegative").toBool(true);
    fitOptions.robust = fit.value("robust").toBool(true);

    // The plant's physical parameters, as saved (every value checked again).
    std::shared_ptr<const sim::PlantParameters> plantParameters;
    if (root.contains("plantParameters")) {
        const QJsonObject saved = root.value("plantParameters").toObject();
        const QString savedSource = saved.value("source").toString();
        QString problem;
        auto parsed = sim::parsePlantParameters(
            QJsonDocument(saved.value("file").toObject()).toJson(),
            savedSource.isEmpty() ? QStringLiteral("plantParameters") : savedSource, plant,
            &problem);
        if (!parsed) {
            return fail(tr("'plantParameters': %1").arg(problem));
        }
        plantParameters = std::make_shared<const sim::PlantParameters>(std::move(*parsed));
    }

    // The demonstration: the file the session names, else the plant's scripted one.
    std::shared_ptr<const core::Demonstration> demonstration;
    QString scriptedStyle = sim::DemonstrationStyles::classic(plant);
    std::uint64_t scriptedSeed = 1;
    const QString source = root.value("demonstration").toString();
    if (!source.isEmpty()) {
        core::FileError fileError;
        auto loaded = core::readDemonstrationCsv(source, &fileError);
        if (!loaded) {
            return fail(tr("its demonstration: %1").arg(fileError.toString()));
        }
        if (loaded->stateDimension() != profile.info.stateDimension() ||
            loaded->actionDimension() != profile.info.actionDimension()) {
            return fail(tr("its demonstration %1 is not a %2 demonstration").arg(source, plant));
        }
        demonstration = std::make_shared<core::Demonstration>(std::move(*loaded));
    } else {
        // The scripted operator the session names (the classic one by default).
        scriptedStyle = root.value("scriptedStyle").toString(scriptedStyle);
        if (!sim::DemonstrationStyles::contains(plant, scriptedStyle)) {
            return fail(tr("'scriptedStyle' must be one of %1")
                            .arg(sim::DemonstrationStyles::names(plant).join(", ")));
        }
        const double seed = root.value("scriptedSeed").toDouble(1.0);
        if (!(seed >= 0.0 && seed <= 9e15) || seed != std::floor(seed)) {
            return fail(tr("'scriptedSeed' must be a whole number from 0 to 9e15"));
        }
        scriptedSeed = static_cast<std::uint64_t>(seed);
        try {  // a plant file the scripted operator cannot drive says so
            demonstration = scripted(plant, scriptedStyle, scriptedSeed, plantParameters.get());
        } catch (const std::invalid_argument& e) {
            return fail(QString::fromStdString(e.what()));
        }
    }

    // The task made as every task is (checked and fitted); only then does the session change.
    sim::Task task;
    try {
        task = sim::makeTask(profile, std::move(demonstration), fitOptions, plantParameters);
    } catch (const std::invalid_argument& e) {
        return fail(QString::fromStdString(e.what()));
    }
    // The identified model, if one was saved and is still this demonstration's. One that cannot
    // be used is left out, and the operator told; the rest of the session opens.
    std::shared_ptr<const sim::IdentificationResult> model;
    QString modelNotice;
    if (root.contains("model")) {
        const QJsonObject saved = root.value("model").toObject();
        QString problem;
        auto read =
            sim::readIdentifiedPlantFile(QJsonDocument(saved.value("file").toObject()).toJson(),
                                         QStringLiteral("model"), plant, &problem);
        if (!read) {
            modelNotice = tr("The identified model saved with it could not be read (%1): "
                             "identify the car again in the Model step.")
                              .arg(problem);
        } else if (saved.value("samples").toInt(-1) != task.demonstration->length()) {
            modelNotice =
                tr("Its demonstration is not the one the saved model was identified "
                   "from: identify the car again in the Model step.");
        } else {
            model = std::make_shared<const sim::IdentificationResult>(std::move(*read));
        }
    }
    task_ = std::move(task);
    model_ = std::move(model);
    applyModelToProfile();
    method_ = method;
    fitOptions_ = fitOptions;
    demonstrationSource_ = source;
    scriptedStyle_ = scriptedStyle;
    scriptedSeed_ = scriptedSeed;
    messages_ = root.value("messages").toArray();  // not an array: none
    QStringList notices;
    if (earlier) {
        notices << tr(
            "Saved by an earlier PRISCA Lab: its PRISCA, PD and ILC parameters were "
            "tuned for an earlier PRISCA, so today's defaults are used instead.");
    }
    if (!modelNotice.isEmpty()) {
        notices << modelNotice;
    }
    notice_ = notices.join(QLatin1Char(' '));
    emit plantChanged(task_.plant);
    emit plantParametersChanged();
    emit demonstrationChanged();
    emit fitChanged();
    emit identifiedModelChanged(QString());
    emit controllerChanged();
    return true;
}

}  // namespace prisca::app
