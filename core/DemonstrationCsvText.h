#pragma once
// The demonstration CSV's text conventions, shared by its reader (DemonstrationCsvReader.cpp)
// and writer (DemonstrationCsvWriter.cpp): the magic line, field trimming, number parsing and
// printing, which names and units survive a header row, and how offending text is quoted in a
// message. Internal to core.

#include "FileIo.h"

#include <QByteArray>
#include <QString>

#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

namespace prisca::core::csvtext {

using Text = std::string_view;

inline constexpr Text kMagic = "prisca-demonstration";
inline constexpr Text kVersion = "1";
inline constexpr const char* kMagicLine = "# prisca-demonstration 1";
// Line numbers are ints, so refuse what could overflow them (and what no recording reaches).
inline constexpr qint64 kMaxBytes = qint64(1) << 30;

inline bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

inline Text trimmed(Text s) {
    while (!s.empty() && isBlank(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && isBlank(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

inline bool equalsIgnoringCase(Text a, Text b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (size_t i = 0; i < a.size(); ++i) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        if (lower(a[i]) != lower(b[i])) {
            return false;
        }
    }
    return true;
}

inline QString toQString(Text s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// Quotes offending text for a message, shortened so one bad field cannot flood a dialog.
inline QString quoted(const QString& s) {
    constexpr int kMaxChars = 40;
    if (s.size() > kMaxChars) {
        return QStringLiteral("'%1...'").arg(s.left(kMaxChars));
    }
    return QStringLiteral("'%1'").arg(s);
}

inline QString quoted(Text s) {
    return quoted(toQString(s));
}

inline void appendNumber(QByteArray& out, double value) {
    appendCsvNumber(out, value);
}

inline QString numberText(double value) {
    QByteArray text;
    appendNumber(text, value);
    return QString::fromLatin1(text);
}

enum class NumberStatus { Ok, Empty, NotANumber, OutOfRange, NotFinite };

// from_chars parses straight from the line buffer: no QString per field, no locale.
inline NumberStatus parseNumber(Text field, double* value) {
    if (field.empty()) {
        return NumberStatus::Empty;
    }
    const char* first = field.data();
    const char* const last = first + field.size();
    // Spreadsheets and pandas accept a leading '+'; from_chars does not.
    if (*first == '+' && field.size() > 1 && first[1] != '+' && first[1] != '-') {
        ++first;
    }
    double parsed = 0.0;
    const auto [end, status] = std::from_chars(first, last, parsed);
    if (status == std::errc::result_out_of_range && end == last) {
        return NumberStatus::OutOfRange;
    }
    if (status != std::errc() || end != last) {
        return NumberStatus::NotANumber;
    }
    if (!std::isfinite(parsed)) {
        return NumberStatus::NotFinite;
    }
    *value = parsed;
    return NumberStatus::Ok;
}

inline bool hasLineBreak(const QString& s) {
    return s.contains(QLatin1Char('\n')) || s.contains(QLatin1Char('\r')) || s.contains(QChar(0));
}

// Why a column name would not survive the header row (pandas, MATLAB), or empty if it would.
inline QString nameProblem(const QString& name) {
    if (name.isEmpty()) {
        return QStringLiteral("is empty");
    }
    if (name.front().isSpace() || name.back().isSpace()) {
        return QStringLiteral("has spaces at its start or end");
    }
    for (const QChar c : name) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f) {
            return QStringLiteral("contains a control character");
        }
        if (c == QLatin1Char(',') || c == QLatin1Char('[') || c == QLatin1Char(']') ||
            c == QLatin1Char('#') || c == QLatin1Char('"')) {
            return QStringLiteral("contains '%1', which CSV readers would misread").arg(c);
        }
    }
    return {};
}

// nameProblem, and a demonstration's state or action name may not be "t" (its time column).
inline QString stateOrActionNameProblem(const QString& name) {
    if (const QString problem = nameProblem(name); !problem.isEmpty()) {
        return problem;
    }
    if (name == QLatin1String("t")) {
        return QStringLiteral("is reserved for the time column");
    }
    return {};
}

// Why a unit would not survive the "name[unit]" list, or empty if it would.
inline QString unitProblem(const QString& unit) {
    for (const QChar c : unit) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f) {
            return QStringLiteral("contains a control character");
        }
        if (c == QLatin1Char(',') || c == QLatin1Char('[') || c == QLatin1Char(']')) {
            return QStringLiteral("contains '%1'").arg(c);
        }
    }
    if (!unit.isEmpty() && (unit.front().isSpace() || unit.back().isSpace())) {
        return QStringLiteral("has spaces at its start or end");
    }
    return {};
}

// Keys of the "# key: value" lines the reader interprets itself (not free metadata).
inline const char* const kReservedKeys[] = {"plant", "dt", "states", "actions"};

// Why a "# key: value" metadata line would not be written back as read, or empty if it would.
// The writer refuses such metadata and the reader such lines, so what one accepts the other does.
inline QString metadataProblem(const QString& key, const QString& value) {
    if (key.trimmed().isEmpty()) {
        return QStringLiteral("a metadata key is empty");
    }
    if (key.trimmed() != key) {
        return QStringLiteral("metadata key %1 has spaces at its start or end").arg(quoted(key));
    }
    if (key.contains(QLatin1Char(':')) || hasLineBreak(key)) {
        return QStringLiteral("metadata key %1 contains ':' or a line break").arg(quoted(key));
    }
    for (const char* reserved : kReservedKeys) {
        if (key.compare(QLatin1String(reserved), Qt::CaseInsensitive) == 0) {
            return QStringLiteral(
                       "metadata key %1 is reserved for the Demonstration field of "
                       "that name")
                .arg(quoted(key));
        }
    }
    if (hasLineBreak(value) || value.trimmed() != value) {
        return QStringLiteral("metadata value of %1 contains a line break or spaces at its ends")
            .arg(quoted(key));
    }
    return {};
}

}  // namespace prisca::core::csvtext
