#include "brdfsim/grd_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "base/diagnostics.h"
#include "base/interrupt_cleanup.h"
#include "base/limits.h"
#include "base/math.h"

namespace gonio {

namespace {

constexpr char kMagic[8] = {'G', 'O', 'N', 'I', 'O', 'G', 'R', 'D'};
constexpr char kEndMagic[8] = {'G', 'R', 'D', 'E', 'N', 'D', '\0', '\0'};
constexpr std::uint32_t kFlagIsotropic = 1, kFlagBaked = 2;
// Where the header's real-valued fields lie (formats.md), for their errors.
constexpr std::uint64_t kEnergyMinOffset = 44, kMassOffset = 68;

bool HostIsLittleEndian() {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

// 64-bit FNV-style hash over 8-byte words: detects corruption at disk speed.
class Checksum {
  public:
    void Add(const void* data, std::size_t n) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        if (fill_ == 0) {  // whole words at once (little-endian host, checked by the callers)
            for (; i + 8 <= n; i += 8) {
                std::memcpy(&word_, bytes + i, 8);
                Flush();
            }
        }
        for (; i < n; ++i) {
            word_ |= static_cast<std::uint64_t>(bytes[i]) << (8 * fill_);
            if (++fill_ == 8) Flush();
        }
    }
    std::uint64_t Value() {
        if (fill_) Flush();
        return hash_;
    }

  private:
    void Flush() {
        hash_ = (hash_ ^ word_) * 0x100000001b3ull;
        hash_ ^= hash_ >> 29;
        word_ = 0;
        fill_ = 0;
    }
    std::uint64_t hash_ = 0xcbf29ce484222325ull, word_ = 0;
    int fill_ = 0;
};

class Writer {
  public:
    explicit Writer(const std::string& path) : path_(path) {
        file_ = std::fopen(path.c_str(), "wb");
        if (!file_) throw GrdIoError(path + ": cannot write: " + std::strerror(errno));
    }
    ~Writer() {
        if (file_) std::fclose(file_);
    }
    void Bytes(const void* data, std::size_t n) {
        checksum_.Add(data, n);
        if (n && std::fwrite(data, 1, n, file_) != n) throw GrdIoError(path_ + ": write error");
    }
    template <typename T>
    void Value(T value) {
        Bytes(&value, sizeof value);
    }
    template <typename T>
    void Array(const std::vector<T>& values) {
        Bytes(values.data(), values.size() * sizeof(T));
    }
    void Finish() {
        Value(checksum_.Value());
        Bytes(kEndMagic, 8);
        if (std::fclose(file_) != 0) {
            file_ = nullptr;
            throw GrdIoError(path_ + ": write error");
        }
        file_ = nullptr;
    }

  private:
    std::string path_;
    std::FILE* file_ = nullptr;
    Checksum checksum_;
};

class Reader {
  public:
    explicit Reader(const std::string& path) : path_(path) {
        file_ = std::fopen(path.c_str(), "rb");
        if (!file_) throw GrdIoError(path + ": cannot open: " + std::strerror(errno));
        struct stat status;
        if (fstat(fileno(file_), &status) == 0 && S_ISREG(status.st_mode)) {
            size_ = static_cast<std::uint64_t>(status.st_size);
            return;
        }
        ReadStreamWhole();
    }
    ~Reader() { std::fclose(file_); }

    [[noreturn]] void Fail(const std::string& what) const { FailAt(offset_, what); }
    [[noreturn]] void FailAt(std::uint64_t offset, const std::string& what) const {
        throw GrdError(path_ + ": " + what + " (at byte " + std::to_string(offset) + ")");
    }
    std::uint64_t Offset() const { return offset_; }
    void Bytes(void* data, std::size_t n, const char* what) {
        if (n > size_ - offset_) {
            Fail(std::string("truncated: file ends inside ") + what + "; expected " +
                 std::to_string(n) + " more bytes, " + std::to_string(size_ - offset_) + " left");
        }
        if (n && std::fread(data, 1, n, file_) != n) throw GrdIoError(path_ + ": read error");
        checksum_.Add(data, n);
        offset_ += n;
    }
    template <typename T>
    T Value(const char* what) {
        T value;
        Bytes(&value, sizeof value, what);
        return value;
    }
    // Checks the count against what is left in the file before allocating.
    template <typename T>
    std::vector<T> Array(std::uint64_t count, const char* what) {
        if (count > (size_ - offset_) / sizeof(T)) {
            Fail(std::string("truncated or corrupt: ") + what + " needs " +
                 std::to_string(count * sizeof(T)) + " bytes, " + std::to_string(size_ - offset_) +
                 " left");
        }
        std::vector<T> values(count);
        Bytes(values.data(), count * sizeof(T), what);
        return values;
    }
    std::uint64_t ChecksumSoFar() { return checksum_.Value(); }
    std::uint64_t Left() const { return size_ - offset_; }

  private:
    // A pipe has no size to check the counts against before allocating: read it whole first,
    // then read the copy in memory as a file.
    void ReadStreamWhole() {
        std::vector<char> chunk(std::size_t(1) << 16);
        std::size_t n;
        while ((n = std::fread(chunk.data(), 1, chunk.size(), file_)) > 0)
            stream_.insert(stream_.end(), chunk.data(), chunk.data() + n);
        const bool failed = std::ferror(file_);
        std::fclose(file_);
        file_ = nullptr;
        if (failed) throw GrdIoError(path_ + ": read error");
        if (stream_.empty()) throw GrdError(path_ + ": empty: not a .grd file");
        size_ = stream_.size();
        file_ = fmemopen(stream_.data(), stream_.size(), "rb");
        if (!file_) throw GrdIoError(path_ + ": cannot read: " + std::strerror(errno));
    }

    std::string path_;
    std::FILE* file_;
    std::vector<char> stream_;  // a pipe's bytes (ReadStreamWhole)
    std::uint64_t size_ = 0, offset_ = 0;
    Checksum checksum_;
};

void ReadHeader(Reader& in, SplatSet& s, int* rings, int* rects, std::uint32_t* flags) {
    char magic[8];
    in.Bytes(magic, 8, "the magic number");
    if (std::memcmp(magic, kMagic, 8) != 0) in.Fail("not a .grd file (no GONIOGRD magic)");
    const auto version = in.Value<std::uint32_t>("the version");
    if (version != kGrdVersion) {
        in.Fail("unsupported .grd version " + std::to_string(version) + " (this build reads " +
                std::to_string(kGrdVersion) + ")");
    }
    *flags = in.Value<std::uint32_t>("the flags");
    s.ncomps = static_cast<int>(in.Value<std::uint32_t>("ncomps"));
    const auto norm = in.Value<std::uint32_t>("the norm");
    const auto horizon = in.Value<std::uint32_t>("the horizon mode");
    *rings = static_cast<int>(in.Value<std::uint32_t>("rings"));
    *rects = static_cast<int>(in.Value<std::uint32_t>("rects"));
    s.params.radius = in.Value<double>("the radius");
    s.params.energyMin = in.Value<double>("energy_min");
    s.paths = in.Value<std::uint64_t>("the path count");
    s.photons = in.Value<std::uint64_t>("the photon count");
    s.mass = in.Value<double>("the normalisation");
    if (*flags & ~(kFlagIsotropic | kFlagBaked)) in.Fail("unknown flags");
    if (s.ncomps < 1 || s.ncomps > kMaxColorComponents)
        in.Fail("ncomps must be in 1.." + std::to_string(kMaxColorComponents));
    if (norm > 2) in.Fail("unknown norm code " + std::to_string(norm));
    if (horizon > 1) in.Fail("unknown horizon code " + std::to_string(horizon));
    if (!(s.params.radius > 0 && s.params.radius <= 1.5708)) in.Fail("radius out of (0, π/2]");
    if (*rings < 1 || *rings > 1000 || *rects < 1 || *rects > 4000) in.Fail("bad rings/rects");
    if (s.paths == 0 || s.photons > s.paths) in.Fail("bad photon or path count");
    if (!(std::isfinite(s.params.energyMin) && s.params.energyMin >= 0))
        in.FailAt(kEnergyMinOffset, "energy_min " + FormatNumber(s.params.energyMin) +
                                        " is not a finite number >= 0");
    if (!(std::isfinite(s.mass) && (horizon == 0 ? s.mass > 0 : s.mass >= 0)))
        in.FailAt(kMassOffset, "the kernel mass " + FormatNumber(s.mass) +
                                   " is not a finite number > 0 (0 in "
                                   "renormalize mode)");
    s.params.norm = static_cast<Norm>(norm);
    s.params.horizon = static_cast<Horizon>(horizon);
    s.params.isotropic = *flags & kFlagIsotropic;
    s.chordRadius2 = static_cast<float>(std::pow(2.0 * std::sin(0.5 * s.params.radius), 2));
    s.invRadius = static_cast<float>(1.0 / s.params.radius);
}

// What formats.md promises of every value a writer produces, with room for rounding: weights,
// energies and baked values finite and at most this in magnitude (their sums stay finite in a
// float), splat centres unit vectors on the upper hemisphere.
constexpr float kMaxMagnitude = 1e30f;
constexpr float kUnitSlack = 1e-3f;

// Checks each value read at `start` (the offset of values[0]); `wrong` says what is wrong with
// one, or nothing.
template <typename T, typename Wrong>
void CheckEach(const Reader& in, std::uint64_t start, const std::vector<T>& values,
               const Wrong& wrong) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::string problem = wrong(values[i], i);
        if (!problem.empty()) in.FailAt(start + i * sizeof(T), problem);
    }
}

std::string WrongMagnitude(float value, const char* what, std::size_t index) {
    if (std::isfinite(value) && std::fabs(value) <= kMaxMagnitude) return {};
    return std::string(what) + " " + std::to_string(index) + " is " + FormatNumber(value) +
           "; expected a finite number within ±1e30";
}

std::string WrongDirection(const SplatGeometry& g, std::size_t index) {
    const float values[] = {g.inX, g.inY, g.inZ, g.thetaIn, g.outX, g.outY, g.outZ};
    const bool finite =
        std::all_of(std::begin(values), std::end(values), [](float v) { return std::isfinite(v); });
    auto unitAbove = [](float x, float y, float z) {
        return std::fabs(std::sqrt(x * x + y * y + z * z) - 1) <= kUnitSlack && z >= -kUnitSlack;
    };
    if (finite && unitAbove(g.inX, g.inY, g.inZ) && unitAbove(g.outX, g.outY, g.outZ) &&
        g.thetaIn >= -kUnitSlack && g.thetaIn <= kHalfPiF + kUnitSlack)
        return {};
    return "splat " + std::to_string(index) +
           "'s centre is not two unit vectors on the upper hemisphere with theta_in in [0, pi/2]";
}

void ReadSplats(Reader& in, SplatSet& s) {
    const auto count = in.Value<std::uint64_t>("the splat count");
    if (count > s.photons) in.Fail("more splats than photons");
    std::uint64_t start = in.Offset();
    s.geometry = in.Array<SplatGeometry>(count, "the splat directions");
    CheckEach(in, start, s.geometry, WrongDirection);
    const auto perSplat = std::size_t(s.ncomps);
    for (auto [values, what] : {std::pair{&s.weights, "the weight of splat"},
                                std::pair{&s.energies, "the energy of splat"}}) {
        start = in.Offset();
        *values = in.Array<float>(count * s.ncomps, what);
        CheckEach(in, start, *values, [&, what = what](float v, std::size_t i) {
            return WrongMagnitude(v, what, i / perSplat);
        });
    }
}

CellLists ReadLists(Reader& in, const SplatSet& s, std::uint64_t expectedCells) {
    CellLists lists;
    const auto cells = in.Value<std::uint64_t>("the cell count");
    if (cells != expectedCells) {
        in.Fail("cell count " + std::to_string(cells) + " does not match rings and rects (" +
                std::to_string(expectedCells) + ")");
    }
    lists.offsets = in.Array<std::uint64_t>(cells + 1, "the cell offsets");
    const auto entries = in.Value<std::uint64_t>("the entry count");
    if (lists.offsets.front() != 0 || lists.offsets.back() != entries) {
        in.Fail("cell offsets do not match the entry count");
    }
    for (std::size_t i = 0; i < cells; ++i) {
        if (lists.offsets[i] > lists.offsets[i + 1]) in.Fail("cell offsets not increasing");
    }
    lists.entries = in.Array<std::uint32_t>(entries, "the cell entries");
    const std::uint32_t images = static_cast<std::uint32_t>(s.NumImages());
    for (std::uint32_t e : lists.entries) {
        if ((e & kSplatMask) >= s.Size() || (e >> kImageShift) >= images) {
            in.Fail("a cell entry names a splat that does not exist");
        }
    }
    return lists;
}

std::unique_ptr<BakedTable> ReadBaked(Reader& in, bool isotropic, int ncomps) {
    std::array<int, 4> dims;
    std::uint64_t size = ncomps;
    for (int& d : dims) {
        d = static_cast<int>(in.Value<std::uint32_t>("the table size"));
        if (d < 1 || d > 1024) in.Fail("table dimension out of 1..1024");
        size *= d;
    }
    if ((isotropic && dims[1] != 1) || dims[0] < 2 || dims[2] < 2) in.Fail("bad table shape");
    const std::uint64_t start = in.Offset();
    std::vector<float> values = in.Array<float>(size, "the baked table");
    CheckEach(in, start, values,
              [](float v, std::size_t i) { return WrongMagnitude(v, "baked value", i); });
    return std::make_unique<BakedTable>(isotropic, ncomps, dims, std::move(values));
}

}  // namespace

const CellLists& GrdFile::Lists() const {
    if (IsIsotropic()) return static_cast<const BrdfIsoGrid&>(*grid).Lists();
    return static_cast<const BrdfGrid&>(*grid).Lists();
}

bool IsGrdFile(const std::string& path) {
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".grd") == 0) return true;
    struct stat status;
    if (stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) return false;
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return false;
    char magic[8];
    const bool isGrd = std::fread(magic, 1, 8, file) == 8 && std::memcmp(magic, kMagic, 8) == 0;
    std::fclose(file);
    return isGrd;
}

GrdFile ReadGrd(const std::string& path) {
    if (!HostIsLittleEndian()) throw GrdIoError(path + ": .grd needs a little-endian host");
    Reader in(path);
    auto splats = std::make_shared<SplatSet>();
    int rings, rects;
    std::uint32_t flags;
    ReadHeader(in, *splats, &rings, &rects, &flags);
    ReadSplats(in, *splats);
    const std::uint64_t outCells = HemisphereGrid::CellCount(rings, rects);
    const std::uint64_t cells = splats->params.isotropic ? rings * outCells : outCells * outCells;
    CellLists lists = ReadLists(in, *splats, cells);
    GrdFile file;
    if (flags & kFlagBaked) file.baked = ReadBaked(in, splats->params.isotropic, splats->ncomps);
    const std::uint64_t expected = in.ChecksumSoFar();
    const auto stored = in.Value<std::uint64_t>("the checksum");
    char end[8];
    in.Bytes(end, 8, "the end marker");
    if (stored != expected) in.Fail("checksum mismatch: the file is corrupt");
    if (std::memcmp(end, kEndMagic, 8) != 0 || in.Left() != 0) in.Fail("trailing garbage");
    file.splats = splats;
    file.rings = rings;
    file.rects = rects;
    if (splats->params.isotropic) {
        file.grid = std::make_unique<BrdfIsoGrid>(splats, rings, rects, std::move(lists));
    } else {
        file.grid = std::make_unique<BrdfGrid>(splats, rings, rects, std::move(lists));
    }
    return file;
}

void WriteGrd(const std::string& path, const SplatSet& s, int rings, int rects,
              const CellLists& lists, const BakedTable* baked) {
    if (!HostIsLittleEndian()) throw GrdIoError(path + ": .grd needs a little-endian host");
    const std::string temp = path + ".tmp." + std::to_string(::getpid());
    const PendingTemporary pending(temp);
    try {
        Writer out(temp);
        out.Bytes(kMagic, 8);
        out.Value<std::uint32_t>(kGrdVersion);
        out.Value<std::uint32_t>((s.params.isotropic ? kFlagIsotropic : 0) |
                                 (baked ? kFlagBaked : 0));
        out.Value<std::uint32_t>(s.ncomps);
        out.Value<std::uint32_t>(static_cast<std::uint32_t>(s.params.norm));
        out.Value<std::uint32_t>(static_cast<std::uint32_t>(s.params.horizon));
        out.Value<std::uint32_t>(rings);
        out.Value<std::uint32_t>(rects);
        out.Value<double>(s.params.radius);
        out.Value<double>(s.params.energyMin);
        out.Value<std::uint64_t>(s.paths);
        out.Value<std::uint64_t>(s.photons);
        out.Value<double>(s.mass);
        out.Value<std::uint64_t>(s.Size());
        out.Array(s.geometry);
        out.Array(s.weights);
        out.Array(s.energies);
        out.Value<std::uint64_t>(lists.NumCells());
        out.Array(lists.offsets);
        out.Value<std::uint64_t>(lists.entries.size());
        out.Array(lists.entries);
        if (baked) {
            for (int d : baked->Dims()) out.Value<std::uint32_t>(d);
            out.Array(baked->Values());
        }
        out.Finish();
    } catch (...) {
        std::remove(temp.c_str());
        throw;
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        throw GrdIoError(path + ": cannot write: " + std::strerror(errno));
    }
}

}  // namespace gonio
