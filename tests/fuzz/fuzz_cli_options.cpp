// The command line's option parsing on arbitrary arguments: CommandLine (parse, number, integer,
// required, values) and the option readers the commands share (run settings, --param, --styles,
// the plant's name). It never crashes or hangs; every refusal is a UsageError (or
// std::invalid_argument) with a one-line message that names the option at fault; every value
// accepted lies in the range it was asked for and passes its own checks.
//
// Input: arguments separated by NUL or newline bytes (one trailing separator is dropped, so a
// corpus file may end with a newline). The first names the option layout: one of the names in
// kLayouts, else a layout chosen by its bytes; the rest are the command's arguments.
#include "FuzzTarget.h"

#include "app/cli/CliSupport.h"
#include "app/cli/TaskSetup.h"
#include "core/FileIo.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/run/RunSetup.h"
#include "sim/tuning/MethodTuning.h"

#include <QRegularExpression>

#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

using namespace prisca;
using app::cli::CommandLine;
using app::cli::UsageError;

namespace {

constexpr long long kLongMin = std::numeric_limits<long long>::min();
constexpr long long kLongMax = std::numeric_limits<long long>::max();
constexpr double kDoubleMax = std::numeric_limits<double>::max();

// A message main() prints after "prisca-cli <command>: ": not empty and one line, with no
// control character (C0, DEL, C1: core::printable escapes them).
void checkMessage(const QString& message) {
    FUZZ_CHECK(!message.isEmpty());
    for (const QChar c : message) {
        const char16_t u = c.unicode();
        FUZZ_CHECK(!(u < 0x20 || u == 0x7f || (u >= 0x80 && u < 0xa0)));
    }
}

// Whether `message` names `text` (as core::printable writes it) as a word of its own: quoted,
// in a list ("Unknown options: a, b.") or after an option's dashes. An empty one ("--=x" is an
// option with no name to Qt) only quoted or as an empty place in a list.
bool names(const QString& message, const QString& text) {
    if (text.isEmpty()) {
        return message.contains(QLatin1String("''")) || message.contains(QLatin1String(": ,")) ||
               message.contains(QLatin1String(", ,")) || message.contains(QLatin1String(", ."));
    }
    static const QString pattern = QStringLiteral("(?:^|['\\s-])%1(?:$|['.,\\s])");
    return QRegularExpression(pattern.arg(QRegularExpression::escape(core::printable(text))))
        .match(message)
        .hasMatch();
}

// A refusal of parse() names an argument it is about: the argument itself, a long option's name
// as given (without its dashes and value), or one letter of a group of short options ("-xy").
bool namesAnArgument(const QString& message, const QStringList& arguments) {
    for (const QString& argument : arguments) {
        if (names(message, argument)) {
            return true;
        }
        if (argument.startsWith(QLatin1String("--"))) {
            if (names(message, argument.mid(2).section(QLatin1Char('='), 0, 0))) {
                return true;
            }
        } else if (argument.startsWith(QLatin1Char('-'))) {
            // Qt reads "-xy=z" as the options x, y, =, z.
            for (qsizetype i = 1; i < argument.size(); ++i) {
                if (names(message, argument.mid(i, 1))) {
                    return true;
                }
            }
        }
    }
    return false;
}

// A refusal by a reader of options `names`: its message starts with "--<name>" for one of them.
void checkRefusal(const char* what, const QStringList& names) {
    const QString message = QString::fromStdString(what);
    checkMessage(message);
    bool named = names.isEmpty();
    for (const QString& name : names) {
        named = named || message.startsWith(QStringLiteral("--") + name);
    }
    FUZZ_CHECK(named);
}

// Runs one option reader: true if it accepted; a refusal is checked (see checkRefusal) and gives
// false; any other exception breaks the property.
template <typename Read>
bool accepted(const QStringList& names, Read read) {
    try {
        read();
        return true;
    } catch (const UsageError& e) {
        checkRefusal(e.what(), names);
    } catch (const std::invalid_argument& e) {
        checkRefusal(e.what(), names);
    } catch (...) {
        FUZZ_CHECK(!"a refusal other than UsageError or std::invalid_argument");
    }
    return false;
}

// A number option read in [minimum, maximum]: accepted only finite and within it.
void readNumber(const CommandLine& line, const QString& name, double minimum, double maximum) {
    double value = 0.0;
    if (accepted({name}, [&] { value = line.number(name, minimum, maximum); })) {
        FUZZ_CHECK(std::isfinite(value) && value >= minimum && value <= maximum);
    }
}

void readInteger(const CommandLine& line, const QString& name, long long minimum,
                 long long maximum) {
    long long value = 0;
    if (accepted({name}, [&] { value = line.integer(name, minimum, maximum); })) {
        FUZZ_CHECK(value >= minimum && value <= maximum);
    }
}

void readRequired(const CommandLine& line, const QString& name) {
    QString value;
    if (accepted({name}, [&] { value = line.required(name); })) {
        FUZZ_CHECK(!value.isEmpty());
    }
}

// The run settings (TaskSetup.h): accepted, each in its range, and past RunSetup's own check
// (training trials >= 0, threads >= 1, levels >= 0).
void readRunSettings(const CommandLine& line, bool training) {
    const sim::RunSettings defaults;
    sim::RunSettings settings;
    QStringList names{"seed", "perturbation", "sensor", "jobs"};
    if (training) {
        names << QStringLiteral("training-trials");
    }
    if (!accepted(names, [&] { app::cli::readRunSettings(line, settings, training); })) {
        return;
    }
    FUZZ_CHECK(settings.seed <= (std::uint64_t(1) << 62));
    FUZZ_CHECK(std::isfinite(settings.perturbation) && settings.perturbation >= 0.0 &&
               settings.perturbation <= 10.0);
    FUZZ_CHECK(std::isfinite(settings.sensor) && settings.sensor >= 0.0 && settings.sensor <= 10.0);
    FUZZ_CHECK(settings.threads >= 1 && settings.threads <= 256);
    FUZZ_CHECK(training ? settings.trainingTrials >= 0 && settings.trainingTrials <= 100000
                        : settings.trainingTrials == defaults.trainingTrials);
    FUZZ_CHECK(settings.trainingTrials >= 0 && settings.threads >= 1 &&
               settings.perturbation >= 0.0 && settings.sensor >= 0.0);
}

// Each plant's profile, made once.
const sim::MethodTuning& profileOf(const QString& plant) {
    static std::map<QString, sim::MethodTuning> profiles;
    auto found = profiles.find(plant);
    if (found == profiles.end()) {
        found =
            profiles.emplace(plant, sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant)))
                .first;
    }
    return found->second;
}

// Every --param applied to the plant's profile (TaskSetup.h): accepted, every parameter of the
// profile passes its own check (MethodParameter::check), and the last one given reads back as
// it was given.
void readMethodParameters(const CommandLine& line, const QString& plant) {
    sim::MethodTuning profile = profileOf(plant);
    const int channels = profile.info.actionDimension();
    if (!accepted({"param"}, [&] { app::cli::applyMethodParameters(line, profile); })) {
        return;
    }
    for (const sim::MethodParameter* parameter : sim::MethodCatalog::parameters()) {
        FUZZ_CHECK(parameter->check(parameter->value(profile), channels).isEmpty());
    }
    const QStringList assignments = line.values("param");
    if (assignments.isEmpty()) {
        return;
    }
    const QString& last = assignments.last();
    const int equals = last.indexOf(QLatin1Char('='));
    FUZZ_CHECK(equals > 0);
    const sim::MethodParameter* parameter =
        sim::MethodCatalog::parameter(last.left(equals).trimmed());
    FUZZ_CHECK(parameter != nullptr);
    QString error;
    const auto given = parameter->parse(last.mid(equals + 1), channels, &error);
    FUZZ_CHECK(given.has_value());
    const Eigen::VectorXd now = parameter->value(profile);
    FUZZ_CHECK(now.size() == given->size());
    for (Eigen::Index i = 0; i < now.size(); ++i) {
        FUZZ_CHECK(now[i] == (*given)[i]);
    }
}

// --plant through checkedPlant: a known plant, or a refusal quoting the name given (the message
// says "unknown plant 'x'", not "--plant").
bool readPlant(const CommandLine& line, QString* plant) {
    const QString given = line.value("plant");
    try {
        *plant = app::cli::checkedPlant(given);
    } catch (const UsageError& e) {
        const QString message = QString::fromStdString(e.what());
        checkMessage(message);
        FUZZ_CHECK(
            message.contains(QLatin1Char('\'') + core::printable(given) + QLatin1Char('\'')));
        return false;
    }
    FUZZ_CHECK(sim::PlantCatalog::contains(*plant));
    return true;
}

// --styles for a known plant: a non-empty list of the plant's styles.
void readStyles(const CommandLine& line, const QString& plant) {
    QStringList styles;
    if (!accepted({"styles"}, [&] { styles = app::cli::stylesOption(line, plant); })) {
        return;
    }
    FUZZ_CHECK(!styles.isEmpty());
    for (const QString& style : styles) {
        FUZZ_CHECK(sim::DemonstrationStyles::contains(plant, style));
    }
}

// One command's options, declared as the command declares them (app/cli/*Command.cpp), then
// read as it reads them; each reader on its own, so a refusal hides none of the others.
struct Layout {
    const char* name;
    const char* formats;  ///< --format's choices, comma-separated (the first is the default)
    void (*declare)(CommandLine&);
    void (*read)(const CommandLine&);
};

const Layout kLayouts[] = {
    {"run", "text,json",
     [](CommandLine& line) {
         line.addValue("plant", "Plant.", "name");
         line.addValue("demo", "Demonstration CSV to repeat.", "file");
         line.addValue("method", "Method.", "name");
         line.addValue("trials", "Trials in a row.", "N", "10");
         app::cli::addRunSettingsOptions(line, "Training trials.");
         line.addValue("mask", "Intuitive mapping.", "signs");
         app::cli::addMethodParameterOptions(line);
         line.addValue("out", "Run log CSV.", "file");
         line.addValue("compare", "Also run this method.", "name");
         line.addValue("plot", "Also draw.", "file");
     },
     [](const CommandLine& line) {
         for (const char* name : {"plant", "method", "out", "demo"}) {
             readRequired(line, name);
         }
         readInteger(line, "trials", 1, 100000);
         readRunSettings(line, true);
         QString plant;
         readMethodParameters(line, readPlant(line, &plant) ? plant : QStringLiteral("slidecar"));
     }},
    {"curve", "text,json",
     [](CommandLine& line) {
         line.addValue("plant", "Plant.", "name", "acrobot");
         line.addValue("demo", "Demonstration CSV.", "file");
         line.addValue("demo-seed", "Seed of the scripted demonstration.", "N", "1");
         line.addValue("styles", "Styles.", "list");
         line.addValue("seed-sets", "Seed sets.", "N", "1");
         line.addValue("methods", "Methods.", "list", "prisca,pgsd,pegasus");
         line.addValue("runs", "Runs.", "N", "20");
         line.addValue("budget", "Steps.", "steps", "64000");
         app::cli::addRunSettingsOptions(line, QString());
         line.addValue("out", "CSV.", "file");
         line.addValue("plot", "Figure.", "file");
         app::cli::addMethodParameterOptions(line);
     },
     [](const CommandLine& line) {
         readRequired(line, "out");
         readInteger(line, "runs", 1, 100000);
         readInteger(line, "budget", 1, 1LL << 40);
         readRunSettings(line, false);
         readInteger(line, "seed-sets", 1, 10000);
         readInteger(line, "demo-seed", 0, 1LL << 62);
         QString plant;
         if (readPlant(line, &plant)) {
             readStyles(line, plant);
             readMethodParameters(line, plant);
         }
     }},
    {"table1", "md,csv,latex,json",
     [](CommandLine& line) {
         line.addValue("plant", "Planar vehicle.", "name", "slidecar");
         line.addValue("demo", "Demonstration CSV.", "file");
         line.addValue("demo-seed", "Seed.", "N", "1");
         line.addValue("styles", "Styles.", "list");
         line.addValue("seed-sets", "Seed sets.", "N", "1");
         line.addValue("trials", "Trials.", "N", "20");
         app::cli::addRunSettingsOptions(line, "Training trials.");
         line.addValue("methods", "Methods.", "list");
         app::cli::addMethodParameterOptions(line);
         line.addValue("out", "Table.", "file");
         line.addValue("plot", "Figure.", "file");
     },
     [](const CommandLine& line) {
         QString plant;
         if (readPlant(line, &plant)) {
             readStyles(line, plant);
             readMethodParameters(line, plant);
         }
         readInteger(line, "seed-sets", 1, 10000);
         readInteger(line, "seed", 0, 1LL << 62);
         readInteger(line, "trials", 1, 100000);
         readRunSettings(line, true);
     }},
    {"simulate", "text,json",
     [](CommandLine& line) {
         line.addValue("plant", "Plant.", "name");
         line.addValue("initial", "Initial state.", "values");
         line.addValue("actions", "Action table.", "file");
         line.addFlag("zero-action", "Zero action.");
         line.addValue("duration", "Simulated time.", "seconds");
         line.addValue("dt", "Control period.", "seconds", "0.025");
         line.addValue("substeps", "Physics steps.", "count", "10");
         line.addValue("out", "Output CSV.", "file");
     },
     [](const CommandLine& line) {
         QString plant;
         readPlant(line, &plant);
         readRequired(line, "out");
         readNumber(line, "dt", 1e-4, 1.0);
         readInteger(line, "substeps", 1, 1000);
         if (line.isSet("duration")) {
             readNumber(line, "duration", 0.0, 86400.0);
         }
     }},
    // The ranges the commands ask for (link, demo, lemma41) and the extremes of the types.
    {"ranges", "text,json,md",
     [](CommandLine& line) {
         for (const char* name : {"rate", "duration", "level", "wide", "tiny", "negative"}) {
             line.addValue(name, "A number.", "x", "1");
         }
         for (const char* name : {"baud", "seed", "any", "count", "offset"}) {
             line.addValue(name, "A whole number.", "N", "1");
         }
         line.addValue("port", "Serial device path.", "path");
         line.addFlag("virtual", "A switch.");
     },
     [](const CommandLine& line) {
         readNumber(line, "rate", 1.0, 1000.0);
         readNumber(line, "duration", 0.0, 86400.0);
         readNumber(line, "level", 0.0, 10.0);
         readNumber(line, "wide", -kDoubleMax, kDoubleMax);
         readNumber(line, "tiny", 1e-300, 1e-290);
         readNumber(line, "negative", -1e6, -1.0);
         readInteger(line, "baud", 0, 10000000);
         readInteger(line, "seed", 0, kLongMax);
         readInteger(line, "any", kLongMin, kLongMax);
         readInteger(line, "count", 1, 1);
         readInteger(line, "offset", kLongMin, -1);
         readRequired(line, "port");
     }},
};

// Standard output into /dev/null while `run` runs: --help prints the help there.
template <typename Run>
bool withoutStdout(Run run) {
    static const int devNull = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    std::fflush(stdout);
    const int saved = ::dup(STDOUT_FILENO);
    ::dup2(devNull, STDOUT_FILENO);
    bool result = false;
    try {
        result = run();
    } catch (...) {
        std::fflush(stdout);
        ::dup2(saved, STDOUT_FILENO);
        ::close(saved);
        throw;
    }
    std::fflush(stdout);
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    QList<QByteArray> tokens{QByteArray()};
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\0' || data[i] == '\n') {
            tokens.append(QByteArray());
        } else {
            tokens.last().append(static_cast<char>(data[i]));
        }
    }
    if (tokens.size() > 1 && tokens.last().isEmpty()) {
        tokens.removeLast();
    }
    const QByteArray& first = tokens.first();
    const Layout* layout = nullptr;
    unsigned sum = 0;
    for (const char c : first) {
        sum += static_cast<unsigned char>(c);
    }
    for (const Layout& l : kLayouts) {
        if (first == l.name) {
            layout = &l;
        }
    }
    if (layout == nullptr) {
        layout = &kLayouts[sum % (sizeof(kLayouts) / sizeof(kLayouts[0]))];
    }
    QStringList arguments;
    for (qsizetype i = 1; i < tokens.size(); ++i) {
        // As main() reads argv.
        arguments << QString::fromLocal8Bit(tokens[i]);
    }

    CommandLine line(QString::fromLatin1(layout->name), QStringLiteral("Fuzzed options."));
    layout->declare(line);
    const QStringList formats = QString::fromLatin1(layout->formats).split(QLatin1Char(','));
    line.addFormat(formats);
    bool parsed = false;
    try {
        if (!withoutStdout([&] { return line.parse(arguments); })) {
            FUZZ_CHECK(line.isSet("help"));
            return 0;
        }
        parsed = true;
    } catch (const UsageError& e) {
        const QString message = QString::fromStdString(e.what());
        checkMessage(message);
        FUZZ_CHECK(namesAnArgument(message, arguments));
    } catch (...) {
        FUZZ_CHECK(!"parse() refused with something other than UsageError");
    }
    if (!parsed) {
        return 0;
    }
    FUZZ_CHECK(formats.contains(line.format()));
    layout->read(line);
    return 0;
}
