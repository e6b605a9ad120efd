// The demonstration CSV reader: a line cursor and a parser that names the line and column of
// anything wrong.
#include "DemonstrationCsv.h"

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

namespace prisca::core {

using namespace csvtext;

namespace {

// Walks the text line by line, accepting LF, CRLF and lone CR endings.
class LineCursor {
  public:
    explicit LineCursor(Text text) : text_(text) {}

    /// The next line without its ending; false at the end of the text.
    bool next(Text* line) {
        if (pos_ >= text_.size()) {
            return false;
        }
        size_t end = pos_;
        while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') {
            ++end;
        }
        *line = text_.substr(pos_, end - pos_);
        pos_ = end;
        if (pos_ < text_.size()) {
            const bool crlf =
                text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n';
            pos_ += crlf ? 2 : 1;
        }
        ++number_;
        return true;
    }

    /// 1-based number of the line last returned by next().
    int number() const { return number_; }

  private:
    Text text_;
    size_t pos_ = 0;
    int number_ = 0;
};

/// One of the "# key: value" lines the reader interprets itself.
struct KnownLine {
    Text value;
    int line = 0;  // 0 while not seen
};

class DemonstrationParser {
  public:
    DemonstrationParser(Text text, const QString& source, const CsvReadOptions& options)
        : cursor_(text), options_(options) {
        error_.path = source;
    }

    std::optional<Demonstration> parse(FileError* error);

  private:
    bool fail(int line, int column, const QString& message);
    bool readMagic();
    bool readMetadata();
    bool readDeclarations();
    bool readEntries(const KnownLine& declaration, const QString& kind, QStringList* names,
                     QStringList* units);
    bool readDt();
    bool checkHeader();
    bool readRows();
    bool checkTiming();
    Demonstration result() const;

    int width() const { return 1 + int(stateNames_.size()) + int(actionNames_.size()); }
    QString columnName(int column) const;  // 1-based
    QString expectedHeader() const;
    QString fieldCountText() const;

    LineCursor cursor_;
    CsvReadOptions options_;
    FileError error_;

    int lastTextLine_ = 0;  // last non-blank line before the header
    int headerLine_ = 0;
    Text header_;
    KnownLine plant_, dt_, states_, actions_;
    QMap<QString, QString> metadata_;
    QStringList stateNames_, stateUnits_, actionNames_, actionUnits_;
    QSet<QString> allNames_;  // state and action names, for the duplicate check
    double dt_value_ = 0.0;
    bool dtInferred_ = false;

    std::vector<double> values_;  // row-major, width() values per row
    std::vector<int> rowLines_;   // file line of each row, for timing errors found later
};

bool DemonstrationParser::fail(int line, int column, const QString& message) {
    error_.line = line;
    error_.column = column;
    error_.message = message;
    return false;
}

std::optional<Demonstration> DemonstrationParser::parse(FileError* error) {
    bool ok = false;
    std::optional<Demonstration> demo;
    // Never let an allocation failure on a huge or hostile file escape to the caller.
    try {
        ok = readMagic() && readMetadata() && readDeclarations() && readDt() && checkHeader() &&
             readRows() && checkTiming();
        if (ok) {
            demo = result();
            const QString problem = demo->validate();
            if (!problem.isEmpty()) {
                ok = fail(0, 0, problem);  // unreachable when the checks above are complete
            }
        }
    } catch (const std::bad_alloc&) {
        ok = fail(0, 0, QStringLiteral("not enough memory to read the demonstration"));
    } catch (...) {
        ok = fail(0, 0, QStringLiteral("internal error while reading the demonstration"));
    }
    if (!ok) {
        if (error) {
            *error = error_;
        }
        return std::nullopt;
    }
    return demo;
}

bool DemonstrationParser::readMagic() {
    Text line;
    if (!cursor_.next(&line)) {
        return fail(1, 0,
                    QStringLiteral("the file is empty; expected the first line '%1'")
                        .arg(QLatin1String(kMagicLine)));
    }
    Text body = trimmed(line);
    const auto missing = [&] {
        return fail(1, 0,
                    QStringLiteral("the first line is %1, not '%2'; is this a PRISCA "
                                   "demonstration file?")
                        .arg(quoted(body), QLatin1String(kMagicLine)));
    };
    if (body.empty() || body.front() != '#') {
        return missing();
    }
    const Text content = trimmed(body.substr(1));
    if (content.substr(0, kMagic.size()) != kMagic ||
        (content.size() > kMagic.size() && !isBlank(content[kMagic.size()]))) {
        return missing();
    }
    const Text version = trimmed(content.substr(kMagic.size()));
    if (version.empty()) {
        return fail(1, 0,
                    QStringLiteral("the first line gives no format version; expected '%1'")
                        .arg(QLatin1String(kMagicLine)));
    }
    if (version != kVersion) {
        return fail(1, 0,
                    QStringLiteral("unsupported format version %1; this program reads version %2")
                        .arg(quoted(version), toQString(kVersion)));
    }
    lastTextLine_ = 1;
    return true;
}

bool DemonstrationParser::readMetadata() {
    Text line;
    while (cursor_.next(&line)) {
        const Text body = trimmed(line);
        if (body.empty()) {
            continue;
        }
        if (body.front() != '#') {
            header_ = body;
            headerLine_ = cursor_.number();
            return true;
        }
        lastTextLine_ = cursor_.number();
        const Text content = trimmed(body.substr(1));
        const size_t colon = content.find(':');
        const Text key = colon == Text::npos ? Text() : trimmed(content.substr(0, colon));
        if (key.empty()) {
            continue;  // a free comment: there is no field to keep it in
        }
        const Text value = trimmed(content.substr(colon + 1));
        KnownLine* known = nullptr;
        KnownLine* const knownLines[] = {&plant_, &dt_, &states_, &actions_};
        for (int i = 0; i < 4; ++i) {
            if (equalsIgnoringCase(key, kReservedKeys[i])) {
                known = knownLines[i];
            }
        }
        if (!known) {
            const QString keyText = toQString(key), valueText = toQString(value);
            if (const QString problem = metadataProblem(keyText, valueText); !problem.isEmpty()) {
                return fail(cursor_.number(), 0, problem);
            }
            metadata_.insert(keyText, valueText);
            continue;
        }
        if (hasLineBreak(toQString(value))) {
            return fail(cursor_.number(), 0,
                        QStringLiteral("the '# %1:' line contains a NUL or a carriage return")
                            .arg(toQString(key)));
        }
        if (known->line != 0) {
            return fail(cursor_.number(), 0,
                        QStringLiteral("a second '# %1:' line; the first is on line %2")
                            .arg(toQString(key))
                            .arg(known->line));
        }
        known->value = value;
        known->line = cursor_.number();
    }
    return true;  // a missing header is reported after the declarations it must match
}

bool DemonstrationParser::readDeclarations() {
    // Where the header row is, or where it should have been.
    const int at = headerLine_ != 0 ? headerLine_ : lastTextLine_ + 1;
    if (states_.line == 0) {
        return fail(at, 0,
                    QStringLiteral("missing the '# states: name[unit], ...' line before the "
                                   "header row"));
    }
    if (actions_.line == 0) {
        return fail(at, 0,
                    QStringLiteral("missing the '# actions: name[unit], ...' line before the "
                                   "header row"));
    }
    return readEntries(states_, QStringLiteral("state"), &stateNames_, &stateUnits_) &&
           readEntries(actions_, QStringLiteral("action"), &actionNames_, &actionUnits_);
}

bool DemonstrationParser::readEntries(const KnownLine& declaration, const QString& kind,
                                      QStringList* names, QStringList* units) {
    if (declaration.value.empty()) {
        return true;  // no channels of this kind
    }
    Text rest = declaration.value;
    for (int index = 1;; ++index) {
        const size_t comma = rest.find(',');
        const Text entry = trimmed(rest.substr(0, comma));
        const auto bad = [&](const QString& why) {
            return fail(
                declaration.line, index,
                QStringLiteral("%1 entry %2 %3 %4").arg(kind).arg(index).arg(quoted(entry), why));
        };
        if (entry.empty()) {
            return fail(declaration.line, index,
                        QStringLiteral("%1 entry %2 is empty").arg(kind).arg(index));
        }
        Text name = entry;
        QString unit = QStringLiteral("1");
        const size_t open = entry.find('[');
        if (open != Text::npos) {
            const size_t close = entry.find(']', open);
            if (close == Text::npos) {
                return bad(QStringLiteral("has a '[' without a closing ']'"));
            }
            if (close + 1 != entry.size()) {
                return bad(QStringLiteral("has text after the unit's closing ']'"));
            }
            name = trimmed(entry.substr(0, open));
            const Text unitText = trimmed(entry.substr(open + 1, close - open - 1));
            if (unitText.find('[') != Text::npos) {
                return bad(QStringLiteral("has a '[' inside its unit"));
            }
            unit = toQString(unitText);
            if (const QString problem = unitProblem(unit); !problem.isEmpty()) {
                return bad(QStringLiteral("has a unit that ") + problem);
            }
        } else if (entry.find(']') != Text::npos) {
            return bad(QStringLiteral("has a ']' without an opening '['"));
        }
        const QString nameString = toQString(name);
        const QString problem = stateOrActionNameProblem(nameString);
        if (!problem.isEmpty()) {
            return bad(QStringLiteral("has a name that ") + problem);
        }
        if (allNames_.contains(nameString)) {  // a set: 10^5 names stay linear
            return bad(QStringLiteral("repeats the name %1; column names must be unique")
                           .arg(quoted(nameString)));
        }
        names->append(nameString);
        allNames_.insert(nameString);
        units->append(unit);
        if (comma == Text::npos) {
            return true;
        }
        rest = rest.substr(comma + 1);
    }
}

bool DemonstrationParser::readDt() {
    if (dt_.line == 0) {
        dtInferred_ = true;  // taken from the median step once the rows are read
        return true;
    }
    switch (parseNumber(dt_.value, &dt_value_)) {
        case NumberStatus::Ok:
            break;
        case NumberStatus::Empty:
            return fail(dt_.line, 0,
                        QStringLiteral("the dt line gives no value; expected the sampling period "
                                       "in seconds, e.g. '# dt: 0.025'"));
        case NumberStatus::NotANumber:
            return fail(dt_.line, 0,
                        QStringLiteral("dt %1 is not a number (expected seconds, e.g. 0.025)")
                            .arg(quoted(dt_.value)));
        case NumberStatus::OutOfRange:
        case NumberStatus::NotFinite:
            return fail(dt_.line, 0,
                        QStringLiteral("dt %1 is not a finite number").arg(quoted(dt_.value)));
    }
    if (!(dt_value_ >= Demonstration::kMinDt && dt_value_ <= Demonstration::kMaxDt)) {
        return fail(dt_.line, 0,
                    QStringLiteral("dt must be from %1 to %2 s, got %3")
                        .arg(Demonstration::kMinDt)
                        .arg(Demonstration::kMaxDt)
                        .arg(quoted(dt_.value)));
    }
    return true;
}

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

}  // namespace

std::optional<Demonstration> parseDemonstrationCsv(const QByteArray& text,
                                                   const QString& sourceName, FileError* error,
                                                   const CsvReadOptions& options) {
    if (text.size() > kMaxBytes) {
        if (error) {
            *error = FileError{sourceName, 0, 0,
                               QStringLiteral("the text is %1 bytes, more than the %2 bytes "
                                              "this reader accepts")
                                   .arg(text.size())
                                   .arg(kMaxBytes)};
        }
        return std::nullopt;
    }
    Text all(text.constData(), size_t(text.size()));
    // Windows editors prepend a UTF-8 byte order mark.
    if (all.substr(0, 3) == Text("\xEF\xBB\xBF")) {
        all.remove_prefix(3);
    }
    return DemonstrationParser(all, sourceName, options).parse(error);
}

std::optional<Demonstration> readDemonstrationCsv(const QString& path, FileError* error,
                                                  const CsvReadOptions& options) {
    const std::optional<QByteArray> text = readFileBounded(path, kMaxBytes, error);
    if (!text) {
        return std::nullopt;
    }
    return parseDemonstrationCsv(*text, path, error, options);
}

}  // namespace prisca::core
