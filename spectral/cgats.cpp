#include "spectral/cgats.h"

#include <cmath>
#include <map>

#include "spectral/number_format.h"
#include "spectral/spectral_error.h"
#include "spectral/text_file.h"

namespace gonio::spectral {

namespace {

struct Token {
    std::string text;
    int line;
};

bool Derived(const std::string& keyword) {
    return keyword.rfind("SPECTRAL_", 0) == 0 || keyword == "NUMBER_OF_FIELDS" ||
           keyword == "NUMBER_OF_SETS";
}

std::string Unquote(const std::string& text) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"')
        return text.substr(1, text.size() - 2);
    return text;
}

// Collects the blank-separated tokens from the line after `*index` up to the line `endMarker`;
// leaves `*index` on that line. A file that ends first is truncated.
std::vector<Token> TokensUntil(const std::vector<std::string>& lines, size_t* index,
                               const std::string& endMarker, const std::string& name) {
    const int beginLine = int(*index) + 1;
    const std::string beginMarker = lines[*index];
    std::vector<Token> tokens;
    for (++*index; *index < lines.size(); ++*index) {
        const std::vector<std::string> words = SplitBlanks(lines[*index]);
        if (!words.empty() && words[0] == endMarker) return tokens;
        if (!words.empty() && words[0][0] == '#') continue;
        for (const std::string& word : words) tokens.push_back({word, int(*index) + 1});
    }
    FailAt(name, int(lines.size()),
           "the file ends before " + endMarker + " (opened at line " + std::to_string(beginLine) +
               "): truncated");
}

}  // namespace

const CgatsSet* CgatsFile::Find(const std::string& sampleId) const {
    for (const CgatsSet& set : sets)
        if (set.sampleId == sampleId) return &set;
    return nullptr;
}

CgatsFile ParseCgats(const std::vector<std::string>& lines, const std::string& name) {
    CgatsFile file;
    std::map<std::string, std::pair<double, int>> numbers;  // numeric keywords and their lines
    std::vector<Token> fields;
    std::vector<std::vector<Token>> dataBlocks;
    bool sawType = false;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string> words = SplitBlanks(lines[i]);
        const int lineNo = int(i) + 1;
        if (words.empty() || words[0][0] == '#') continue;
        if (!sawType) {
            file.fileType = words[0];
            sawType = true;
            continue;
        }
        if (words[0] == "BEGIN_DATA_FORMAT") {
            fields = TokensUntil(lines, &i, "END_DATA_FORMAT", name);
            continue;
        }
        if (words[0] == "BEGIN_DATA") {
            if (fields.empty()) FailAt(name, lineNo, "BEGIN_DATA before any BEGIN_DATA_FORMAT");
            dataBlocks.push_back(TokensUntil(lines, &i, "END_DATA", name));
            continue;
        }
        if (words[0] == "END_DATA" || words[0] == "END_DATA_FORMAT")
            FailAt(name, lineNo, words[0] + " without its BEGIN");
        // A keyword line: the keyword and the rest of the line as its value.
        const std::string& keyword = words[0];
        const size_t at = lines[i].find(keyword) + keyword.size();
        std::string value = lines[i].substr(at);
        while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.erase(0, 1);
        while (!value.empty() &&
               (value.back() == ' ' || value.back() == '\t' || value.back() == '\r'))
            value.pop_back();
        if (Derived(keyword)) {
            double number = 0;
            if (!ParseNumber(Unquote(value), &number))
                FailAt(name, lineNo, keyword + " expects a number, got \"" + value + "\"");
            numbers[keyword] = {number, lineNo};
        } else {
            file.keywords.emplace_back(keyword, value);
        }
    }
    if (!sawType) FailAt(name, 0, "empty file: not a CGATS file");
    if (fields.empty())
        FailAt(name, int(lines.size()), "no BEGIN_DATA_FORMAT: not a CGATS spectral file");
    if (dataBlocks.empty()) FailAt(name, int(lines.size()), "no BEGIN_DATA: the file has no data");

    // The columns: SAMPLE_ID, SPEC_<nm>, and others (ignored).
    int idColumn = -1;
    std::vector<int> specColumns;
    std::vector<double> wavelengths;
    for (size_t f = 0; f < fields.size(); ++f) {
        const std::string& field = fields[f].text;
        if (field == "SAMPLE_ID") {
            idColumn = int(f);
        } else if (field.rfind("SPEC_", 0) == 0) {
            double nm = 0;
            if (!ParseNumber(field.substr(5), &nm))
                FailAt(name, fields[f].line, "field " + field + " does not name a wavelength");
            if (!wavelengths.empty() && !(nm > wavelengths.back()))
                FailAt(name, fields[f].line,
                       "field " + field + " does not follow a shorter wavelength");
            specColumns.push_back(int(f));
            wavelengths.push_back(nm);
        }
    }
    if (wavelengths.size() < 2)
        FailAt(name, fields.front().line, "the field list names fewer than 2 SPEC_ wavelengths");
    auto checkCount = [&](const char* keyword, double expected) {
        auto it = numbers.find(keyword);
        if (it != numbers.end() && std::abs(it->second.first - expected) > 1e-6)
            FailAt(name, it->second.second,
                   std::string(keyword) + " says " + ShortestDecimal(it->second.first) +
                       " but the data has " + ShortestDecimal(expected));
    };
    checkCount("SPECTRAL_BANDS", double(wavelengths.size()));
    checkCount("NUMBER_OF_FIELDS", double(fields.size()));
    // The header is authoritative: SPEC_ field names are not always nanometres (colord's
    // CIE-A.sp names its 1 nm fields SPEC_300000 ... SPEC_830000). With START, END and the band
    // count the samples are evenly spaced between them; without, the field names give them.
    const auto start = numbers.find("SPECTRAL_START_NM"), end = numbers.find("SPECTRAL_END_NM");
    if (start != numbers.end() && end != numbers.end()) {
        if (!(end->second.first > start->second.first))
            FailAt(name, end->second.second,
                   "SPECTRAL_END_NM must exceed SPECTRAL_START_NM (" +
                       ShortestDecimal(start->second.first) + ")");
        const double lo = start->second.first, hi = end->second.first;
        const size_t n = wavelengths.size();
        for (size_t i = 0; i < n; ++i) wavelengths[i] = lo + (hi - lo) * double(i) / double(n - 1);
        wavelengths.back() = hi;
    }

    size_t setCount = 0;
    for (const std::vector<Token>& block : dataBlocks) {
        if (block.size() % fields.size() != 0) {
            const int line = block.empty() ? 0 : block.back().line;
            FailAt(name, line,
                   "the data block holds " + std::to_string(block.size()) +
                       " values, not a whole number of sets of " + std::to_string(fields.size()) +
                       " fields (a row is short or long)");
        }
        for (size_t row = 0; row < block.size() / fields.size(); ++row) {
            const Token* base = &block[row * fields.size()];
            std::vector<double> values(specColumns.size());
            for (size_t s = 0; s < specColumns.size(); ++s) {
                const Token& token = base[specColumns[s]];
                if (!ParseNumber(token.text, &values[s]))
                    FailAt(name, token.line,
                           "expected a number for SPEC_" + ShortestDecimal(wavelengths[s]) +
                               ", got \"" + token.text + "\"");
            }
            CgatsSet set;
            if (idColumn >= 0) set.sampleId = Unquote(base[idColumn].text);
            set.spectrum = Spectrum(wavelengths, std::move(values));
            file.sets.push_back(std::move(set));
            ++setCount;
        }
    }
    checkCount("NUMBER_OF_SETS", double(setCount));
    return file;
}

CgatsFile ReadCgats(const std::string& path) { return ParseCgats(ReadTextLines(path), path); }

std::string FormatCgats(const CgatsFile& file) {
    if (file.sets.empty()) throw SpectralError("a CGATS file needs at least one set");
    const std::vector<double>& wavelengths = file.sets.front().spectrum.Wavelengths();
    bool withIds = false;
    for (const CgatsSet& set : file.sets) {
        if (set.spectrum.Wavelengths() != wavelengths)
            throw SpectralError("all sets of a CGATS file must share one sampling");
        if (set.spectrum.GetInterpolation() != Interpolation::Linear)
            throw SpectralError("a CGATS file holds sampled spectra, not Catmull-Rom curves");
        withIds |= !set.sampleId.empty();
    }
    const int fieldCount = int(wavelengths.size()) + (withIds ? 1 : 0);
    std::string text = file.fileType + "\n";
    for (const auto& [keyword, value] : file.keywords) text += keyword + "\t" + value + "\n";
    text += "SPECTRAL_START_NM\t" + ShortestDecimal(wavelengths.front()) + "\n";
    text += "SPECTRAL_END_NM\t" + ShortestDecimal(wavelengths.back()) + "\n";
    text += "SPECTRAL_BANDS\t" + std::to_string(wavelengths.size()) + "\n";
    text += "NUMBER_OF_FIELDS\t" + std::to_string(fieldCount) + "\n";
    text += "NUMBER_OF_SETS\t" + std::to_string(file.sets.size()) + "\n";
    text += "BEGIN_DATA_FORMAT\n";
    if (withIds) text += "SAMPLE_ID\t";
    for (size_t i = 0; i < wavelengths.size(); ++i)
        text +=
            "SPEC_" + ShortestDecimal(wavelengths[i]) + (i + 1 < wavelengths.size() ? "\t" : "\n");
    text += "END_DATA_FORMAT\nBEGIN_DATA\n";
    for (const CgatsSet& set : file.sets) {
        if (withIds) text += (set.sampleId.empty() ? std::string("\"\"") : set.sampleId) + "\t";
        const std::vector<double>& values = set.spectrum.Values();
        for (size_t i = 0; i < values.size(); ++i)
            text += ShortestDecimal(values[i]) + (i + 1 < values.size() ? "\t" : "\n");
    }
    text += "END_DATA\n";
    return text;
}

void WriteCgats(const std::string& path, const CgatsFile& file) {
    WriteTextFileAtomically(path, FormatCgats(file));
}

}  // namespace gonio::spectral
