#pragma once
// A point cloud as bake3d() writes and texture3d() reads it (PRMan's point-based baking): points
// with a position, a normal and named channels of floats, kept in the documented binary `.ptc`
// file of docs/file-formats.md ("Point clouds"), and looked up by the nearest point (a k-d tree
// over the positions, built when the file is read).

#include <Imath/ImathVec.h>

#include <string>
#include <vector>

namespace gonio {

class PointCloud {
  public:
    struct Channel {
        std::string name;
        int width = 0;   // floats per point
        int offset = 0;  // of its first float in a point's values
    };

    // Adds a channel (before any point); false if the name is taken.
    bool AddChannel(const std::string& name, int width);
    const std::vector<Channel>& Channels() const { return channels_; }
    const Channel* FindChannel(const std::string& name) const;
    // Floats per point over all channels.
    int ValueWidth() const { return valueWidth_; }

    // Appends a point with ValueWidth() values.
    void Add(const Imath::V3f& P, const Imath::V3f& N, const float* values);
    size_t Size() const { return P_.size(); }
    const Imath::V3f& Position(size_t i) const { return P_[i]; }
    const Imath::V3f& Normal(size_t i) const { return N_[i]; }
    const float* Values(size_t i) const { return &values_[i * size_t(valueWidth_)]; }

    // Puts the points in an order that depends only on their contents (position, normal, then
    // values), so that a file baked by any number of threads is the same byte for byte.
    void Sort();

    // The file's bytes, and the cloud from them; false with the reason (a foreign, truncated or
    // inconsistent file).
    std::string Serialize() const;
    bool Parse(const std::string& bytes, std::string* why);

    // Builds the k-d tree that Nearest searches; once, after the last Add.
    void BuildIndex();
    // The index of the point nearest to P (Euclidean); -1 when the cloud is empty.
    long Nearest(const Imath::V3f& P) const;

  private:
    void Build(size_t begin, size_t end, int depth);
    void Search(size_t begin, size_t end, int depth, const Imath::V3f& P, long* best,
                float* bestDistance2) const;

    std::vector<Channel> channels_;
    int valueWidth_ = 0;
    std::vector<Imath::V3f> P_, N_;
    std::vector<float> values_;
    std::vector<size_t> tree_;  // point indices, each range's median at its middle
};

}  // namespace gonio
