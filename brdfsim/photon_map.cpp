#include "brdfsim/photon_map.h"

#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

#include "base/limits.h"
#include "base/math.h"

namespace gonio {

namespace {

constexpr std::size_t kChunkBytes = 8 << 20;
constexpr float kAngleSlack = 1e-4f;  // rounding in files written by other programs
// Beyond what any tracer writes, values lose the map's precision or overflow the splats' floats
// (a weight divides by the probability): φ turned more than twice round, densities further
// from 1 than 1e±12 per steradian, energies beyond ±1e6.
constexpr float kMaxPhi = 4 * kPiF;
constexpr float kMinProbability = 1e-12f, kMaxProbability = 1e12f;
constexpr float kMaxEnergy = 1e6f;

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Parses the numbers of one line into `out`; returns how many or -1 on a non-number.
int ParseNumbers(const char*& p, const char* end, float* out, int capacity) {
    int n = 0;
    while (true) {
        while (p < end && IsBlank(*p)) ++p;
        if (p >= end || *p == '\n') return n;
        float value;
        const auto result = std::from_chars(p, end, value);
        if (result.ec != std::errc() ||
            (result.ptr < end && !IsBlank(*result.ptr) && *result.ptr != '\n')) {
            return -1;
        }
        if (n < capacity) out[n] = value;
        ++n;
        p = result.ptr;
    }
}

std::string CheckPhoton(const float* row, int stride) {
    for (int i = 0; i < stride; ++i) {
        if (!std::isfinite(row[i])) return "expected finite numbers";
    }
    if (row[kThetaIn] < -kAngleSlack || row[kThetaIn] > kHalfPiF + kAngleSlack) {
        return "expected theta_in in [0, pi/2] radians";
    }
    if (row[kThetaOut] < -kAngleSlack || row[kThetaOut] > kHalfPiF + kAngleSlack) {
        return "expected theta_out in [0, pi/2] radians (photons escaping downwards have no line)";
    }
    if (std::fabs(row[kPhiIn]) > kMaxPhi || std::fabs(row[kPhiOut]) > kMaxPhi)
        return "expected phi_in and phi_out within ±4π radians";
    if (!(row[kProbability] >= kMinProbability && row[kProbability] <= kMaxProbability))
        return "expected a probability density in [1e-12, 1e12] per steradian";
    for (int i = kFirstColour; i < stride; ++i)
        if (std::fabs(row[i]) > kMaxEnergy) return "expected energies within ±1e6";
    return {};
}

}  // namespace

struct PhotonMapReader::Piece {
    std::vector<float> rows;
    std::vector<std::uint16_t> bounces;
    std::uint64_t lines = 0;
    std::uint64_t errorLine = 0;  // 1-based within the piece; 0 if none
    std::string error;
};

PhotonMapReader::PhotonMapReader(const std::string& path) : path_(path) {
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_) throw PhotonMapIoError(path + ": cannot open: " + std::strerror(errno));
    std::string line;
    int c;
    while ((c = std::fgetc(file_)) != EOF && c != '\n') {
        line.push_back(static_cast<char>(c));
        if (line.size() > 256) break;
    }
    header_.count = ParseHeaderLine(line);
}

PhotonMapReader::~PhotonMapReader() {
    if (file_) std::fclose(file_);
}

std::uint64_t PhotonMapReader::ParseHeaderLine(const std::string& line) {
    const char* p = line.data();
    const char* end = p + line.size();
    std::uint64_t numbers[2] = {0, 0};
    int n = 0;
    while (true) {
        while (p < end && IsBlank(*p)) ++p;
        if (p >= end) break;
        if (n == 2) {  // a third word: the bounce tag, or not a photon map header
            const std::string_view word(p, end - p);
            if (word.substr(0, 7) == "bounces" &&
                word.find_first_not_of(" \t\r", 7) == std::string_view::npos) {
                header_.bounces = true;
                break;
            }
            n = -1;
            break;
        }
        const auto result = std::from_chars(p, end, numbers[n]);
        if (result.ec != std::errc() || (result.ptr < end && !IsBlank(*result.ptr))) {
            n = -1;
            break;
        }
        p = result.ptr;
        ++n;
    }
    if (n != 1 && n != 2) {
        throw PhotonMapError(path_ +
                             ":1: expected the photon count (optionally followed by the number "
                             "of traced paths and the word bounces) on the first line; is this a "
                             "photon map?");
    }
    header_.paths = n == 2 ? numbers[1] : numbers[0];
    if (header_.paths < numbers[0]) {
        throw PhotonMapError(path_ + ":1: traced paths (" + std::to_string(header_.paths) +
                             ") fewer than photons (" + std::to_string(numbers[0]) + ")");
    }
    return numbers[0];
}

void PhotonMapReader::ParsePieces(const char* begin, const char* end, std::vector<float>& rows,
                                  std::vector<std::uint16_t>* bounces) {
    const int tag = header_.bounces ? 1 : 0;  // the bounce column after the colours
    if (ncomps_ == 0) {  // the first photon line fixes the number of colour values
        const char* p = begin;
        std::uint64_t line = lineNumber_ + 1;
        while (p < end) {
            const char* q = p;
            float scratch[kFirstColour + kMaxColorComponents];
            const int n = ParseNumbers(q, end, scratch, kFirstColour + kMaxColorComponents);
            if (n == 0) {  // a blank line
                p = q + 1;
                ++line;
                continue;
            }
            if (n < 0) {
                throw PhotonMapError(path_ + ":" + std::to_string(line) + ": expected numbers");
            }
            if (n < kFirstColour + 1 + tag) {
                throw PhotonMapError(path_ + ":" + std::to_string(line) +
                                     ": expected theta_in phi_in theta_out phi_out probability "
                                     "and at least one colour value" +
                                     (tag ? " and the bounce count" : ""));
            }
            if (n - kFirstColour - tag > kMaxColorComponents) {
                throw PhotonMapError(path_ + ":" + std::to_string(line) + ": expected at most " +
                                     std::to_string(kMaxColorComponents) + " colour values, got " +
                                     std::to_string(n - kFirstColour - tag));
            }
            ncomps_ = n - kFirstColour - tag;
            break;
        }
        if (ncomps_ == 0) return;
    }
    const int stride = kFirstColour + ncomps_;
    const int fileStride = stride + tag;
    const std::size_t bytes = end - begin;
    const int numPieces = static_cast<int>(std::clamp<std::size_t>(bytes >> 18, 1, 16));
    std::vector<const char*> cuts(numPieces + 1, end);
    cuts[0] = begin;
    for (int i = 1; i < numPieces; ++i) {
        const char* guess = std::max(cuts[i - 1], begin + bytes * i / numPieces);
        const char* nl = static_cast<const char*>(std::memchr(guess, '\n', end - guess));
        cuts[i] = nl ? nl + 1 : end;
    }
    pieces_.resize(numPieces);
    tbb::parallel_for(0, numPieces, [&](int i) {
        Piece& piece = pieces_[i];
        piece.rows.clear();
        piece.bounces.clear();
        piece.lines = 0;
        piece.errorLine = 0;
        piece.error.clear();
        piece.rows.reserve((cuts[i + 1] - cuts[i]) / (stride * 8) + 16);
        std::vector<float> row(fileStride);
        const char* p = cuts[i];
        while (p < cuts[i + 1]) {
            ++piece.lines;
            const int n = ParseNumbers(p, cuts[i + 1], row.data(), fileStride);
            if (n == 0) {  // a blank line
                ++p;
                continue;
            }
            std::string error;
            if (n < 0) {
                error = "expected numbers";
            } else if (n != fileStride) {
                error = "expected " + std::to_string(fileStride) + " values (5 + " +
                        std::to_string(ncomps_) + " colours" + (tag ? " + the bounce count" : "") +
                        ", as on the first photon line), got " + std::to_string(n);
            } else {
                error = CheckPhoton(row.data(), stride);
                const float b = row[fileStride - 1];
                if (error.empty() && tag && !(b >= 0 && b <= kMaxBounces && b == std::floor(b)))
                    error = "expected a bounce count, an integer in [0, 65535]";
            }
            if (!error.empty()) {
                piece.error = error;
                piece.errorLine = piece.lines;
                return;
            }
            piece.rows.insert(piece.rows.end(), row.begin(), row.begin() + stride);
            if (tag) piece.bounces.push_back(static_cast<std::uint16_t>(row[stride]));
            ++p;  // past the newline
        }
    });
    std::size_t added = 0;
    for (int i = 0; i < numPieces; ++i) added += pieces_[i].rows.size();
    if (rows.capacity() < rows.size() + added) {
        // Room for the rest of the file at once: growing by doubling would copy it again.
        const std::size_t rest = (header_.count - photonsRead_) * stride;
        rows.reserve(rows.size() + std::max(added, std::min(rest, std::size_t(1) << 28)));
    }
    for (int i = 0; i < numPieces; ++i) {
        const Piece& piece = pieces_[i];
        if (!piece.error.empty()) {
            throw PhotonMapError(path_ + ":" + std::to_string(lineNumber_ + piece.errorLine) +
                                 ": " + piece.error);
        }
        const std::uint64_t photons = piece.rows.size() / stride;
        if (photonsRead_ + photons > header_.count) {
            throw PhotonMapError(path_ + ": more photon lines than the " +
                                 std::to_string(header_.count) + " the first line announces");
        }
        photonsRead_ += photons;
        lineNumber_ += piece.lines;
        rows.insert(rows.end(), piece.rows.begin(), piece.rows.end());
        if (bounces) bounces->insert(bounces->end(), piece.bounces.begin(), piece.bounces.end());
    }
}

bool PhotonMapReader::ReadBatch(std::size_t maxPhotons, std::vector<float>& rows,
                                std::vector<std::uint16_t>* bounces) {
    if (eof_) return false;
    const std::size_t before = rows.size();
    if (buffer_.empty()) buffer_.resize(2 * kChunkBytes);
    while (!eof_ && (ncomps_ == 0 || (rows.size() - before) / (kFirstColour + ncomps_) <
                                         std::max<std::size_t>(maxPhotons, 1))) {
        const std::size_t got = std::fread(buffer_.data() + carry_, 1, kChunkBytes, file_);
        if (got < kChunkBytes) {
            if (std::ferror(file_)) throw PhotonMapIoError(path_ + ": read error");
            eof_ = true;
        }
        const char* begin = buffer_.data();
        const char* end = begin + carry_ + got;
        const char* cut = end;
        if (!eof_) {
            while (cut > begin && cut[-1] != '\n') --cut;
            if (cut == begin) throw PhotonMapError(path_ + ": a line longer than 8 MB");
        }
        ParsePieces(begin, cut, rows, bounces);
        carry_ = end - cut;
        std::memmove(buffer_.data(), cut, carry_);
    }
    if (eof_ && photonsRead_ != header_.count) {
        throw PhotonMapError(path_ + ": truncated: the first line announces " +
                             std::to_string(header_.count) + " photons, the file holds " +
                             std::to_string(photonsRead_));
    }
    return rows.size() > before || !eof_;
}

PhotonMap ReadPhotonMap(const std::string& path) {
    PhotonMapReader reader(path);
    PhotonMap map;
    map.paths = reader.Header().paths;
    while (reader.ReadBatch(1 << 20, map.rows, &map.bounces)) {
    }
    map.ncomps = reader.NumComponents();
    return map;
}

PhotonMapHeader ReadPhotonMapHeader(const std::string& path) {
    return PhotonMapReader(path).Header();
}

PhotonMapWriter::PhotonMapWriter(const std::string& path, const PhotonMapHeader& header, int ncomps)
    : path_(path),
      tempPath_(path + ".tmp." + std::to_string(::getpid())),
      pending_(tempPath_),
      header_(header),
      ncomps_(ncomps) {
    if (ncomps < 1) throw PhotonMapError(path + ": a photon needs at least one colour value");
    file_ = std::fopen(tempPath_.c_str(), "wb");
    if (!file_) throw PhotonMapIoError(tempPath_ + ": cannot write: " + std::strerror(errno));
    std::string first = std::to_string(header.count);
    if (header.paths != header.count || header.bounces) first += " " + std::to_string(header.paths);
    if (header.bounces) first += " bounces";
    first += "\n";
    buffer_.assign(first.begin(), first.end());
}

PhotonMapWriter::~PhotonMapWriter() {
    if (file_) {
        std::fclose(file_);
        std::remove(tempPath_.c_str());
    }
}

void PhotonMapWriter::Append(const float* row, std::uint16_t bounces) {
    char text[32];
    const int stride = kFirstColour + ncomps_;
    for (int i = 0; i < stride; ++i) {
        const auto result = std::to_chars(text, text + sizeof text, row[i]);
        buffer_.insert(buffer_.end(), text, result.ptr);
        buffer_.push_back(i + 1 < stride ? ' ' : '\n');
    }
    if (header_.bounces) {
        buffer_.back() = ' ';
        const auto result = std::to_chars(text, text + sizeof text, bounces);
        buffer_.insert(buffer_.end(), text, result.ptr);
        buffer_.push_back('\n');
    }
    ++written_;
    if (buffer_.size() > (1 << 20)) {
        if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
            throw PhotonMapIoError(tempPath_ + ": write error");
        }
        buffer_.clear();
    }
}

void PhotonMapWriter::Close() {
    if (written_ != header_.count) {
        throw PhotonMapError(path_ + ": wrote " + std::to_string(written_) +
                             " photons, announced " + std::to_string(header_.count));
    }
    const bool ok = std::fwrite(buffer_.data(), 1, buffer_.size(), file_) == buffer_.size();
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!ok || !closed || std::rename(tempPath_.c_str(), path_.c_str()) != 0) {
        std::remove(tempPath_.c_str());
        throw PhotonMapIoError(path_ + ": cannot write: " + std::strerror(errno));
    }
}

void WritePhotonMap(const std::string& path, const PhotonMap& map) {
    const bool tagged = !map.bounces.empty();
    if (tagged && map.bounces.size() != map.Size())
        throw PhotonMapError(path + ": bounce counts for some photons only");
    PhotonMapWriter writer(path, {map.Size(), map.paths, tagged}, map.ncomps);
    for (std::size_t i = 0; i < map.Size(); ++i)
        writer.Append(map.Row(i), tagged ? map.bounces[i] : 0);
    writer.Close();
}

}  // namespace gonio
