// The demonstration CSV reader's second half: the header, the rows, the timing and the result.
#include "DemonstrationCsv.h"

#include "DemonstrationCsvReader_p.h"
#include "DemonstrationCsvText.h"

#include <QSet>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <new>
#include <string_view>
#include <system_error>
#include <vector>

namespace prisca::core::csvparse {

QString DemonstrationParser::columnName(int column) const {
    const int n = int(stateNames_.size());
    if (column <= 1) {
        return QStringLiteral("t");
    }
    if (column <= 1 + n) {
        return stateNames_.value(column - 2);
    }
    return actionNames_.value(column - 2 - n);
}

QString DemonstrationParser::expectedHeader() const {
    QString header = QStringLiteral("t");
    for (const QString& name : stateNames_ + actionNames_) {
        header += QLatin1Char(',') + name;
    }
    return quoted(header);
}

QString DemonstrationParser::fieldCountText() const {
    return QStringLiteral("%1 (t, %2 states, %3 actions)")
        .arg(width())
        .arg(stateNames_.size())
        .arg(actionNames_.size());
}

bool DemonstrationParser::checkHeader() {
    if (headerLine_ == 0) {
        return fail(
            lastTextLine_ + 1, 0,
            QStringLiteral("missing the header row %1 after the '#' lines").arg(expectedHeader()));
    }
    const int expected = width();
    const int got = int(std::count(header_.begin(), header_.end(), ',')) + 1;
    Text rest = header_;
    for (int column = 1; column <= std::min(expected, got); ++column) {
        const size_t comma = rest.find(',');
        const Text field = trimmed(rest.substr(0, comma));
        rest = comma == Text::npos ? Text() : rest.substr(comma + 1);
        const QString want = columnName(column);
        if (toQString(field) == want) {
            continue;
        }
        double number = 0.0;
        if (column == 1 && parseNumber(field, &number) == NumberStatus::Ok) {
            return fail(headerLine_, 1,
                        QStringLiteral("missing the header row: this line starts with the number "
                                       "%1; expected the header %2 first")
                            .arg(quoted(field), expectedHeader()));
        }
        if (column == 1) {
            return fail(headerLine_, 1,
                        QStringLiteral("header column 1 is %1 but must be 't' (the time column)")
                            .arg(quoted(field)));
        }
        const bool isState = column <= 1 + int(stateNames_.size());
        return fail(
            headerLine_, column,
            QStringLiteral("header column %1 is %2 but the '# %3:' line declares %4 there")
                .arg(column)
                .arg(quoted(field), isState ? QStringLiteral("states") : QStringLiteral("actions"),
                     quoted(want)));
    }
    if (got < expected) {
        return fail(headerLine_, got + 1,
                    QStringLiteral("the header row has %1 columns, expected %2; column %3 %4 is "
                                   "missing")
                        .arg(got)
                        .arg(fieldCountText())
                        .arg(got + 1)
                        .arg(quoted(columnName(got + 1))));
    }
    if (got > expected) {
        return fail(headerLine_, expected + 1,
                    QStringLiteral("the header row has %1 columns, expected %2; column %3 is "
                                   "not declared in the '# states:' or '# actions:' line")
                        .arg(got)
                        .arg(fieldCountText())
                        .arg(expected + 1));
    }
    return true;
}

bool DemonstrationParser::readRows() {
    const int expected = width();
    Text line;
    while (cursor_.next(&line)) {
        const Text body = trimmed(line);
        if (body.empty() || body.front() == '#') {
            continue;  // pandas (comment='#', skip_blank_lines) skips these too
        }
        const int lineNumber = cursor_.number();
        // Count first, so a short row is reported as short rather than by its first bad field.
        const int got = int(std::count(body.begin(), body.end(), ',')) + 1;
        if (got != expected) {
            const int column = got < expected ? got + 1 : expected + 1;
            return fail(
                lineNumber, column,
                QStringLiteral("expected %1 fields (t, %2 states, %3 actions) but got %4; %5")
                    .arg(expected)
                    .arg(stateNames_.size())
                    .arg(actionNames_.size())
                    .arg(got)
                    .arg(got < expected ? QStringLiteral("column %1 %2 is missing")
                                              .arg(column)
                                              .arg(quoted(columnName(column)))
                                        : QStringLiteral("column %1 is extra").arg(column)));
        }
        const size_t base = values_.size();
        values_.resize(base + size_t(expected));
        Text rest = body;
        for (int column = 1; column <= expected; ++column) {
            const size_t comma = rest.find(',');
            const Text field = trimmed(rest.substr(0, comma));
            rest = comma == Text::npos ? Text() : rest.substr(comma + 1);
            const auto bad = [&](const QString& what) {
                return fail(lineNumber, column,
                            what.arg(quoted(field), quoted(columnName(column))));
            };
            switch (parseNumber(field, &values_[base + size_t(column - 1)])) {
                case NumberStatus::Ok:
                    break;
                case NumberStatus::Empty:
                    return fail(lineNumber, column,
                                QStringLiteral("column %1 is empty; expected a number")
                                    .arg(quoted(columnName(column))));
                case NumberStatus::NotANumber:
                    return bad(QStringLiteral("value %1 in column %2 is not a number"));
                case NumberStatus::OutOfRange:
                    return bad(
                        QStringLiteral("value %1 in column %2 is out of the range of a "
                                       "double"));
                case NumberStatus::NotFinite:
                    return bad(QStringLiteral("value %1 in column %2 is not finite"));
            }
            const double bound =
                column == 1 ? Demonstration::kMaxAbsTime : Demonstration::kMaxAbsValue;
            if (!(std::abs(values_[base + size_t(column - 1)]) <= bound)) {
                return bad(QStringLiteral("value %1 in column %2 is beyond +-") +
                           numberText(bound) + QStringLiteral(", more than the format can mean"));
            }
        }
        if (!rowLines_.empty()) {
            const double time = values_[base];
            const double previous = values_[base - size_t(expected)];
            if (!(time > previous)) {
                return fail(lineNumber, 1,
                            QStringLiteral("time %1 is not after %2 on line %3; column 't' must "
                                           "strictly increase")
                                .arg(numberText(time), numberText(previous))
                                .arg(rowLines_.back()));
            }
        }
        if (rowLines_.size() >= size_t(INT_MAX)) {
            return fail(lineNumber, 0, QStringLiteral("too many rows"));
        }
        rowLines_.push_back(lineNumber);
    }
    return true;
}

bool DemonstrationParser::checkTiming() {
    if (rowLines_.empty()) {
        return fail(headerLine_ + 1, 0, QStringLiteral("no data rows after the header row"));
    }
    const size_t rows = rowLines_.size();
    const size_t stride = size_t(width());
    if (dtInferred_) {
        if (rows < 2) {
            return fail(rowLines_.front(), 1,
                        QStringLiteral("no '# dt:' line, and a single row cannot tell the "
                                       "sampling period; add e.g. '# dt: 0.025'"));
        }
        // The median ignores a few dropped or doubled samples; the check below still rejects them.
        std::vector<double> steps(rows - 1);
        for (size_t k = 1; k < rows; ++k) {
            steps[k - 1] = values_[k * stride] - values_[(k - 1) * stride];
        }
        const size_t middle = steps.size() / 2;
        std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(middle), steps.end());
        dt_value_ = steps[middle];
        if (steps.size() % 2 == 0) {
            const double below =
                *std::max_element(steps.begin(), steps.begin() + std::ptrdiff_t(middle));
            dt_value_ = 0.5 * (below + dt_value_);
        }
        if (!(dt_value_ >= Demonstration::kMinDt && dt_value_ <= Demonstration::kMaxDt)) {
            return fail(rowLines_[middle + 1], 1,
                        QStringLiteral("the median time step is %1 s; it must be from %2 to "
                                       "%3 s (or give '# dt:')")
                            .arg(numberText(dt_value_))
                            .arg(Demonstration::kMinDt)
                            .arg(Demonstration::kMaxDt));
        }
    }
    const double tolerance = options_.dtTolerance >= 0.0 ? options_.dtTolerance : 0.0;
    for (size_t k = 1; k < rows; ++k) {
        const double step = values_[k * stride] - values_[(k - 1) * stride];
        if (std::abs(step - dt_value_) > tolerance * dt_value_) {
            return fail(rowLines_[k], 1,
                        QStringLiteral("time step %1 s from line %2 differs from dt %3 s (%4) by "
                                       "more than %5%; samples must be evenly spaced")
                            .arg(QString::number(step, 'g', 6))
                            .arg(rowLines_[k - 1])
                            .arg(numberText(dt_value_),
                                 dtInferred_ ? QStringLiteral("the median step")
                                             : QStringLiteral("from line %1").arg(dt_.line))
                            .arg(QString::number(tolerance * 100.0, 'g', 3)));
        }
    }
    return true;
}

Demonstration DemonstrationParser::result() const {
    Demonstration demo;
    demo.plant = toQString(plant_.value);
    demo.dt = dt_value_;
    demo.stateNames = stateNames_;
    demo.stateUnits = stateUnits_;
    demo.actionNames = actionNames_;
    demo.actionUnits = actionUnits_;
    demo.metadata = metadata_;
    const Eigen::Index rows = Eigen::Index(rowLines_.size());
    const Eigen::Index n = stateNames_.size();
    const Eigen::Index m = actionNames_.size();
    const Eigen::Index stride = 1 + n + m;
    demo.time.resize(rows);
    demo.states.resize(rows, n);
    demo.actions.resize(rows, m);
    for (Eigen::Index k = 0; k < rows; ++k) {
        const double* row = values_.data() + k * stride;
        demo.time[k] = row[0];
        for (Eigen::Index c = 0; c < n; ++c) {
            demo.states(k, c) = row[1 + c];
        }
        for (Eigen::Index c = 0; c < m; ++c) {
            demo.actions(k, c) = row[1 + n + c];
        }
    }
    return demo;
}

}  // namespace prisca::core::csvparse
