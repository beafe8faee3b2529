#include "renderer/photon/photon_frame.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/math.h"
#include "base/shard_range.h"
#include "base/system_memory.h"
#include "brdfsim/photon_map.h"
#include "renderer/raytrace/ray_scene.h"

namespace gonio {
namespace {

constexpr float kDegrees = kPiF / 180;

// Fails early, before minutes of tracing, when the map could not be written.
bool CheckWritable(const std::string& path, const FileLoc& loc, Diagnostics& diagnostics) {
    const std::string probe = path + ".probe." + std::to_string(::getpid());
    std::FILE* f = std::fopen(probe.c_str(), "wb");
    if (!f) {
        diagnostics.Error(
            loc, "BRDFLight: cannot write the photon map '" + path + "': " + std::strerror(errno));
        return false;
    }
    std::fclose(f);
    std::remove(probe.c_str());
    return true;
}

bool WriteMap(const std::string& path, const PhotonTraceResult& result, bool bounces,
              const FileLoc& loc, Diagnostics& diagnostics) {
    try {
        const uint64_t count = result.stats.escapedUp;
        PhotonMapWriter writer(path, {count, result.stats.paths, bounces}, result.ncomps);
        const size_t stride = kFirstColour + result.ncomps;
        for (size_t i = 0; i < count; ++i)
            writer.Append(result.rows.data() + i * stride, result.bounces[i]);
        writer.Close();
        return true;
    } catch (const std::exception& e) {
        diagnostics.Error(loc, std::string("BRDFLight: ") + e.what());
        return false;
    }
}

// A located error, instead of std::bad_alloc, for more photon paths than this machine holds.
bool PhotonsFitInMemory(const Frame& frame, const BrdfLightOptions& options, uint64_t paths,
                        Diagnostics& diagnostics) {
    const double needed = PhotonTraceBytes(paths, frame.options.colorComponents);
    const double memory = PhysicalMemoryBytes();
    if (memory == 0 || needed <= memory) return true;
    diagnostics.Error(options.loc,
                      "BRDFLight: " + std::to_string(paths) + " photon paths need " +
                          ByteSize(needed) + ", more than the " + ByteSize(memory) +
                          " of this machine's memory: trace fewer, with different seeds, and "
                          "merge the maps (gonio brdf merge)");
    return false;
}

}  // namespace

std::string PhotonSummary(const std::string& output, const PhotonStats& s) {
    const double paths = std::max<double>(s.paths, 1);
    char line[512];
    std::snprintf(
        line, sizeof line,
        "BRDFLight: %llu paths -> %s: %llu photons escaped up, %llu down, %llu lost "
        "(%llu missed the geometry, %llu at the bounce limit), %llu absorbed; "
        "mean bounces %.3f; albedo",
        static_cast<unsigned long long>(s.paths), output.c_str(),
        static_cast<unsigned long long>(s.escapedUp),
        static_cast<unsigned long long>(s.escapedDown), static_cast<unsigned long long>(s.Lost()),
        static_cast<unsigned long long>(s.missed), static_cast<unsigned long long>(s.bounceLimit),
        static_cast<unsigned long long>(s.absorbed), s.bounces / paths);
    std::string text = line;
    for (double e : s.energyUp) {
        std::snprintf(line, sizeof line, " %.4f", e / paths);
        text += line;
    }
    std::snprintf(line, sizeof line, "; %.3f s, %.3f M paths/s on %d thread%s", s.seconds,
                  s.seconds > 0 ? s.paths / s.seconds * 1e-6 : 0.0, s.threads,
                  s.threads == 1 ? "" : "s");
    return text + line;
}

bool TracePhotonFrame(const Frame& frame, const RenderSettings& settings, Diagnostics& diagnostics,
                      PhotonStats* stats) {
    BrdfLightOptions options;
    // Scene errors are reported and return true: the render exits 1 for them, 2 only when the
    // map cannot be written.
    if (!ReadBrdfLightOptions(frame, diagnostics, &options)) return true;
    const std::string output =
        settings.outputOverride.empty() ? options.textureName : settings.outputOverride;
    if (frame.shapes.empty() && frame.instances.empty()) {
        diagnostics.Error(options.loc,
                          "BRDFLight: the scene has no geometry to trace photons through "
                          "(expected micro geometry between WorldBegin and WorldEnd)");
        return true;
    }
    if (!CheckWritable(output, options.loc, diagnostics)) return false;
    // Each path's random numbers depend on the seed and its index only (photon_tracer.h), so
    // the shards' maps, merged in shard order, are the unsplit run's map row for row.
    const ShardRange shard =
        ShardOf(uint64_t(options.rays), settings.photonShard, settings.photonShards);
    if (!PhotonsFitInMemory(frame, options, shard.count, diagnostics)) return true;

    const RayScene scene(frame, diagnostics, RayScene::Traversal::kFast);
    const int errors = diagnostics.ErrorCount();
    const MicroBrdfTable brdfs = BuildMicroBrdfTable(frame, diagnostics);
    if (diagnostics.ErrorCount() > errors) return true;  // a bad micro BRDF: nothing traced
    PhotonTraceSettings trace;
    trace.paths = shard.count;
    trace.firstPath = shard.first;
    trace.area = options.area;
    trace.isotropic = options.isotropic;
    trace.averageAzimuth = options.averageAzimuth;
    trace.seed = options.hasSeed ? options.seed : settings.seed;
    trace.maxDepth = options.maxDepth;
    trace.periodic = options.periodic;
    trace.thetaMin = options.thetaMin * kDegrees;
    trace.thetaMax = options.thetaMax * kDegrees;
    trace.progress = settings.progress || ::isatty(STDERR_FILENO);
    const PhotonTraceResult result = TracePhotons(frame, scene, brdfs, trace);
    if (stats) *stats = result.stats;
    if (!WriteMap(output, result, options.bounces, options.loc, diagnostics)) return false;
    std::fprintf(stderr, "%s\n", PhotonSummary(output, result.stats).c_str());
    return true;
}

}  // namespace gonio
