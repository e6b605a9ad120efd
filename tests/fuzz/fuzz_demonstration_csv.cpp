// The demonstration CSV reader on arbitrary bytes: it never crashes, and what it accepts is a
// valid demonstration within the format's bounds that the writer writes and the reader reads
// back unchanged.
#include "FuzzTarget.h"

#include "core/DemonstrationCsv.h"

#include <QByteArray>

using namespace prisca::core;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray text(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    FileError error;
    const auto demo = parseDemonstrationCsv(text, QStringLiteral("fuzz"), &error);
    if (!demo) {
        FUZZ_CHECK(!error.message.isEmpty());
        const QString message = error.toString();
        for (const QChar c : message) {
            FUZZ_CHECK(c.unicode() >= 0x20 && c.unicode() != 0x7f);  // one printable line
        }
        return 0;
    }
    FUZZ_CHECK(demo->validate().isEmpty());
    FUZZ_CHECK(demo->dt >= Demonstration::kMinDt && demo->dt <= Demonstration::kMaxDt);
    const QByteArray written = formatDemonstrationCsv(*demo);
    FUZZ_CHECK(!written.isEmpty());
    const auto back = parseDemonstrationCsv(written, QStringLiteral("fuzz again"), &error);
    FUZZ_CHECK(back);
    FUZZ_CHECK(back->states == demo->states && back->actions == demo->actions);
    FUZZ_CHECK(back->time == demo->time && back->dt == demo->dt);
    FUZZ_CHECK(back->stateNames == demo->stateNames && back->actionNames == demo->actionNames);
    return 0;
}
