// The session reader on arbitrary bytes: it never crashes, a refused session leaves the session
// as it was, and an accepted one is a consistent task.
#include "FuzzTarget.h"

#include "app/LabSession.h"

#include <QCoreApplication>

using prisca::app::LabSession;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static LabSession* const session = [] {
        auto* s = new LabSession;
        s->setPlant(QStringLiteral("slidecar"));
        return s;
    }();
    const QString plantBefore = session->plant();
    const auto demoBefore = session->demonstration();
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    if (!session->fromJson(json, QStringLiteral("fuzz"), &error)) {
        FUZZ_CHECK(!error.isEmpty());
        FUZZ_CHECK(session->plant() == plantBefore && session->demonstration() == demoBefore);
        return 0;
    }
    FUZZ_CHECK(session->demonstration() != nullptr);
    FUZZ_CHECK(session->task().fit.b.allFinite());
    // Put back the state every input starts from, so inputs do not depend on each other.
    if (session->plant() != QLatin1String("slidecar") ||
        !session->demonstrationSource().isEmpty()) {
        session->setPlant(QStringLiteral("slidecar"));
    }
    return 0;
}
