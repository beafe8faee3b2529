#pragma once
// .grd: an optimised BRDF on disk (the thesis's GPBRDFGrid write()/read()), here a versioned,
// little-endian binary file: header, splats, per-cell splat lists, an optional baked table and a
// checksum. docs/formats.md documents the layout byte by byte.

#include <memory>
#include <stdexcept>
#include <string>

#include "brdfsim/baked_table.h"
#include "brdfsim/brdf_grid.h"

namespace gonio {

// The file is not a .grd, or is truncated or corrupt: bad input data.
class GrdError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// The file cannot be opened, read or written.
class GrdIoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

constexpr std::uint32_t kGrdVersion = 1;

struct GrdFile {
    std::shared_ptr<const SplatSet> splats;
    int rings = 0, rects = 0;
    std::unique_ptr<Brdf> grid;         // BrdfGrid or BrdfIsoGrid
    std::unique_ptr<BakedTable> baked;  // null when the file has no table

    bool IsIsotropic() const { return splats->Params().isotropic; }
    const CellLists& Lists() const;
    // The fastest representation: the baked table where there is one.
    const Brdf& Fastest() const { return baked ? static_cast<const Brdf&>(*baked) : *grid; }
};

// Reads a .grd from a file or a pipe (which is read whole first: counts are checked against the
// size before anything is allocated).
GrdFile ReadGrd(const std::string& path);
// Whether `path` names a grid rather than a photon map: its name ends in .grd, or it is a
// regular file that starts with the .grd magic. (A pipe cannot be looked into and read again.)
bool IsGrdFile(const std::string& path);
// Written under a temporary name and renamed when complete.
void WriteGrd(const std::string& path, const SplatSet& splats, int rings, int rects,
              const CellLists& lists, const BakedTable* baked);

}  // namespace gonio
