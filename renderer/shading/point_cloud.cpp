#include "renderer/shading/point_cloud.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

namespace gonio {

namespace {

constexpr char kMagic[8] = {'G', 'O', 'N', 'I', 'O', 'P', 'T', 'C'};
constexpr uint32_t kVersion = 1;
constexpr uint32_t kMaxNameLength = 1024;
constexpr uint32_t kMaxChannelWidth = 64;  // a colour of up to 64 ColorSamples

template <typename T>
void Put(std::string* out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // little-endian hosts only, as the .grd writer
    out->append(bytes, sizeof(T));
}

// Reads the file front to back; every read past the end fails.
class Reader {
  public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <typename T>
    bool Get(T* value) {
        if (bytes_.size() - pos_ < sizeof(T)) return false;
        std::memcpy(value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return true;
    }
    bool GetText(size_t length, std::string* text) {
        if (bytes_.size() - pos_ < length) return false;
        *text = bytes_.substr(pos_, length);
        pos_ += length;
        return true;
    }
    size_t Left() const { return bytes_.size() - pos_; }

  private:
    const std::string& bytes_;
    size_t pos_ = 0;
};

}  // namespace

bool PointCloud::AddChannel(const std::string& name, int width) {
    if (FindChannel(name)) return false;
    channels_.push_back({name, width, valueWidth_});
    valueWidth_ += width;
    return true;
}

const PointCloud::Channel* PointCloud::FindChannel(const std::string& name) const {
    for (const Channel& c : channels_)
        if (c.name == name) return &c;
    return nullptr;
}

void PointCloud::Add(const Imath::V3f& P, const Imath::V3f& N, const float* values) {
    P_.push_back(P);
    N_.push_back(N);
    values_.insert(values_.end(), values, values + valueWidth_);
}

void PointCloud::Sort() {
    std::vector<size_t> order(Size());
    std::iota(order.begin(), order.end(), size_t(0));
    auto less = [&](size_t a, size_t b) {
        for (int k = 0; k < 3; ++k)
            if (P_[a][k] != P_[b][k]) return P_[a][k] < P_[b][k];
        for (int k = 0; k < 3; ++k)
            if (N_[a][k] != N_[b][k]) return N_[a][k] < N_[b][k];
        return std::lexicographical_compare(Values(a), Values(a) + valueWidth_, Values(b),
                                            Values(b) + valueWidth_);
    };
    std::sort(order.begin(), order.end(), less);
    PointCloud sorted;
    sorted.channels_ = channels_;
    sorted.valueWidth_ = valueWidth_;
    for (size_t i : order) sorted.Add(P_[i], N_[i], Values(i));
    *this = std::move(sorted);
}

std::string PointCloud::Serialize() const {
    std::string out(kMagic, sizeof(kMagic));
    Put(&out, kVersion);
    Put(&out, uint32_t(channels_.size()));
    for (const Channel& c : channels_) {
        Put(&out, uint32_t(c.name.size()));
        out += c.name;
        Put(&out, uint32_t(c.width));
    }
    Put(&out, uint64_t(Size()));
    for (size_t i = 0; i < Size(); ++i) {
        for (int k = 0; k < 3; ++k) Put(&out, P_[i][k]);
        for (int k = 0; k < 3; ++k) Put(&out, N_[i][k]);
        for (int k = 0; k < valueWidth_; ++k) Put(&out, Values(i)[k]);
    }
    return out;
}

bool PointCloud::Parse(const std::string& bytes, std::string* why) {
    *this = PointCloud();
    auto fail = [&](const std::string& reason) {
        *why = reason;
        *this = PointCloud();
        return false;
    };
    if (bytes.size() < sizeof(kMagic) || bytes.compare(0, sizeof(kMagic), kMagic, 8) != 0)
        return fail("not a gonio point cloud (no GONIOPTC magic)");
    Reader in(bytes);
    std::string magic;
    uint32_t version = 0, channelCount = 0;
    in.GetText(sizeof(kMagic), &magic);
    if (!in.Get(&version) || version != kVersion)
        return fail("point-cloud version " + std::to_string(version) + ", this gonio reads " +
                    std::to_string(kVersion));
    if (!in.Get(&channelCount) || channelCount > 1024) return fail("a bad channel count");
    for (uint32_t c = 0; c < channelCount; ++c) {
        uint32_t length = 0, width = 0;
        std::string name;
        if (!in.Get(&length) || length == 0 || length > kMaxNameLength ||
            !in.GetText(length, &name) || !in.Get(&width))
            return fail("truncated in its channel list");
        if (width == 0 || width > kMaxChannelWidth)
            return fail("channel '" + name + "' has width " + std::to_string(width));
        if (!AddChannel(name, int(width))) return fail("channel '" + name + "' appears twice");
    }
    uint64_t count = 0;
    if (!in.Get(&count)) return fail("truncated before its point count");
    const uint64_t pointBytes = (6 + uint64_t(valueWidth_)) * sizeof(float);
    if (count > in.Left() / pointBytes || count * pointBytes != in.Left())
        return fail("holds " + std::to_string(in.Left()) + " bytes of points, not " +
                    std::to_string(count) + " points of " + std::to_string(pointBytes));
    std::vector<float> values(static_cast<size_t>(valueWidth_));
    for (uint64_t i = 0; i < count; ++i) {
        Imath::V3f P, N;
        for (int k = 0; k < 3; ++k) in.Get(&P[k]);
        for (int k = 0; k < 3; ++k) in.Get(&N[k]);
        for (float& v : values) in.Get(&v);
        if (!std::isfinite(P.x) || !std::isfinite(P.y) || !std::isfinite(P.z))
            return fail("point " + std::to_string(i) + " has a position that is not finite");
        Add(P, N, values.data());
    }
    return true;
}

void PointCloud::BuildIndex() {
    tree_.resize(Size());
    std::iota(tree_.begin(), tree_.end(), size_t(0));
    Build(0, tree_.size(), 0);
}

// Each range [begin, end) keeps its median along axis depth % 3 at its middle, the smaller
// coordinates before it and the larger after.
void PointCloud::Build(size_t begin, size_t end, int depth) {
    if (end - begin < 2) return;
    const size_t mid = begin + (end - begin) / 2;
    const int axis = depth % 3;
    std::nth_element(tree_.begin() + long(begin), tree_.begin() + long(mid),
                     tree_.begin() + long(end), [&](size_t a, size_t b) {
                         return P_[a][axis] < P_[b][axis] || (P_[a][axis] == P_[b][axis] && a < b);
                     });
    Build(begin, mid, depth + 1);
    Build(mid + 1, end, depth + 1);
}

void PointCloud::Search(size_t begin, size_t end, int depth, const Imath::V3f& P, long* best,
                        float* bestDistance2) const {
    if (begin >= end) return;
    const size_t mid = begin + (end - begin) / 2;
    const size_t i = tree_[mid];
    const float d2 = (P_[i] - P).length2();
    // Ties go to the lower index: the answer does not depend on the search order.
    if (d2 < *bestDistance2 || (d2 == *bestDistance2 && long(i) < *best)) {
        *bestDistance2 = d2;
        *best = long(i);
    }
    const int axis = depth % 3;
    const float along = P[axis] - P_[i][axis];
    const bool lowFirst = along < 0;
    if (lowFirst)
        Search(begin, mid, depth + 1, P, best, bestDistance2);
    else
        Search(mid + 1, end, depth + 1, P, best, bestDistance2);
    if (along * along <= *bestDistance2) {
        if (lowFirst)
            Search(mid + 1, end, depth + 1, P, best, bestDistance2);
        else
            Search(begin, mid, depth + 1, P, best, bestDistance2);
    }
}

long PointCloud::Nearest(const Imath::V3f& P) const {
    long best = -1;
    float bestDistance2 = INFINITY;
    Search(0, tree_.size(), 0, P, &best, &bestDistance2);
    return best;
}

}  // namespace gonio
