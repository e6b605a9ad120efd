#pragma once

// The demonstration CSV reader's line cursor and parser, shared by its sources
// (DemonstrationCsvReader.cpp: the magic line, metadata, declarations and dt;
// DemonstrationCsvRows.cpp: the header, the rows, the timing and the result).

#include "DemonstrationCsv.h"
#include "DemonstrationCsvText.h"

#include <QMap>
#include <QSet>
#include <QStringList>

#include <optional>
#include <vector>

namespace prisca::core::csvparse {

using namespace csvtext;

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

}  // namespace prisca::core::csvparse
