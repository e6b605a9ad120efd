// The run log writer on arbitrary names, units and numbers built from the input: it never
// crashes, refuses what it cannot write, and what it writes is plain CSV whose every row has
// the header's field count and reads back to the same numbers (NaN stays NaN).
#include "FuzzTarget.h"

#include "core/RunLogCsv.h"

#include <QList>

#include <cmath>
#include <cstring>

using namespace prisca::core;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) {
        return 0;
    }
    const int columns = 1 + data[0] % 6;
    const int rows = data[1] % 8;
    std::size_t at = 2;
    const auto text = [&](int length) {
        QByteArray bytes;
        for (int i = 0; i < length && at < size; ++i) {
            bytes += char(data[at++]);
        }
        return QString::fromUtf8(bytes);
    };
    RunLog log;
    log.plant = text(4);
    log.method = text(4);
    std::memcpy(&log.dt, data + std::min(at, size),
                std::min<std::size_t>(8, size - std::min(at, size)));
    at = std::min(at + 8, size);
    for (int c = 0; c < columns; ++c) {
        log.columns << text(3);
        log.units << text(2);
    }
    log.rows.resize(rows, columns);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            double v = 0.0;
            const std::size_t n = std::min<std::size_t>(8, size - at);
            std::memcpy(&v, data + at, n);
            at += n;
            log.rows(r, c) = v;
        }
    }
    QString problem;
    const QByteArray written = formatRunLogCsv(log, &problem);
    if (written.isEmpty()) {
        FUZZ_CHECK(!problem.isEmpty());
        return 0;
    }
    QList<QByteArray> lines;
    for (const QByteArray& line : written.split('\n')) {
        if (!line.isEmpty() && !line.startsWith('#')) {
            lines << line;
        }
    }
    FUZZ_CHECK(lines.size() == rows + 1);  // the header row and the data rows
    for (int r = 0; r <= rows; ++r) {
        const QList<QByteArray> fields = lines[r].split(',');
        FUZZ_CHECK(fields.size() == columns);
        if (r == 0) {
            continue;
        }
        for (int c = 0; c < columns; ++c) {
            const double expected = log.rows(r - 1, c);
            bool ok = false;
            const double got = fields[c].toDouble(&ok);
            FUZZ_CHECK(std::isnan(expected) ? fields[c].toLower().contains("nan")
                                            : ok && got == expected);
        }
    }
    return 0;
}
