// The demonstration CSV reader: a line cursor and a parser that names the line and column of
// anything wrong.
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

namespace prisca::core {

using namespace csvtext;

namespace csvparse {

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

}  // namespace csvparse

using csvparse::DemonstrationParser;

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
