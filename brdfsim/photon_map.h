#pragma once
// Photon maps (thesis Appendix C.2): an ASCII file whose first line holds the photon count, then
// one photon per line: theta_in phi_in theta_out phi_out probability c1 ... cn (radians). The
// first line may carry a second number, the traced paths (photons that escaped downwards or were
// lost count there but have no line); the estimator divides by it. A third word `bounces` there
// says every line ends with one more integer, the surface hits of the photon's path (1: once
// scattered), which the in-memory rows keep apart. docs/formats.md has the rules.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/interrupt_cleanup.h"

namespace gonio {

// A malformed photon map; what() reads "file:line: expected ..." where a line is known.
class PhotonMapError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// An I/O failure (missing file, unwritable folder): a usage error, not bad data.
class PhotonMapIoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Column order of a photon row.
enum PhotonColumn { kThetaIn = 0, kPhiIn, kThetaOut, kPhiOut, kProbability, kFirstColour };

struct PhotonMapHeader {
    std::uint64_t count = 0;  // photon lines
    std::uint64_t paths = 0;  // traced paths, >= count
    bool bounces = false;     // each line ends with the photon's bounce count
};

constexpr std::uint32_t kMaxBounces = 65535;  // the largest bounce count a map holds

// Photons in memory as rows of 5 + ncomps floats.
struct PhotonMap {
    int ncomps = 0;
    std::uint64_t paths = 0;
    std::vector<float> rows;
    std::vector<std::uint16_t> bounces;  // one per row for a tagged map, else empty

    int Stride() const { return kFirstColour + ncomps; }
    std::size_t Size() const { return ncomps ? rows.size() / Stride() : 0; }
    const float* Row(std::size_t i) const { return rows.data() + i * Stride(); }
};

// Streams a photon map in batches, parsing with std::from_chars on both cores, so a map larger
// than memory can be processed and a loaded map is held only once.
class PhotonMapReader {
  public:
    explicit PhotonMapReader(const std::string& path);  // reads and checks the header
    ~PhotonMapReader();
    PhotonMapReader(const PhotonMapReader&) = delete;
    PhotonMapReader& operator=(const PhotonMapReader&) = delete;

    const PhotonMapHeader& Header() const { return header_; }
    // Colour values per photon; known after the first batch (0 before, or for an empty map).
    int NumComponents() const { return ncomps_; }
    // Appends up to about `maxPhotons` rows to `rows` (and, for a tagged map, their bounce
    // counts to `bounces` when given); returns false once the file is exhausted (after
    // checking that the photon count matches the header).
    bool ReadBatch(std::size_t maxPhotons, std::vector<float>& rows,
                   std::vector<std::uint16_t>* bounces = nullptr);

  private:
    struct Piece;
    void ParsePieces(const char* begin, const char* end, std::vector<float>& rows,
                     std::vector<std::uint16_t>* bounces);
    std::uint64_t ParseHeaderLine(const std::string& line);

    std::string path_;
    std::FILE* file_ = nullptr;
    PhotonMapHeader header_;
    int ncomps_ = 0;
    std::uint64_t photonsRead_ = 0;
    std::uint64_t lineNumber_ = 1;  // lines consumed so far
    std::vector<char> buffer_;      // allocated once: carry + one chunk
    std::vector<Piece> pieces_;     // per-thread parse results, their storage reused
    std::size_t carry_ = 0;         // bytes of an incomplete line at the front of buffer_
    bool eof_ = false;
};

PhotonMap ReadPhotonMap(const std::string& path);
PhotonMapHeader ReadPhotonMapHeader(const std::string& path);

// Writes a photon map under a temporary name and renames it on Close(); a writer destroyed
// without Close() (an error on the way) removes the temporary file, so no half file remains.
class PhotonMapWriter {
  public:
    PhotonMapWriter(const std::string& path, const PhotonMapHeader& header, int ncomps);
    ~PhotonMapWriter();
    PhotonMapWriter(const PhotonMapWriter&) = delete;
    PhotonMapWriter& operator=(const PhotonMapWriter&) = delete;

    // `bounces` is written for a tagged header and ignored otherwise.
    void Append(const float* row, std::uint16_t bounces = 0);
    void Close();

  private:
    std::string path_, tempPath_;
    PendingTemporary pending_;  // tempPath_, removed if the run is interrupted
    std::FILE* file_ = nullptr;
    PhotonMapHeader header_;
    int ncomps_;
    std::uint64_t written_ = 0;
    std::vector<char> buffer_;
};

void WritePhotonMap(const std::string& path, const PhotonMap& map);

}  // namespace gonio
