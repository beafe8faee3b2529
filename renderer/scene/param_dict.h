#pragma once
// A typed parameter list (pbrt-v4's ParameterDictionary in spirit): the scene builder types an
// Option, Attribute or Display parameter list once, by inline declaration, Declare or the
// standard table (standard_options.h), and every later reader asks for a value by its bare
// name. Each entry remembers where the RIB gave it and whether anybody read it, so that after
// the frame the parameters that had no effect can be reported at their location.

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "base/file_loc.h"
#include "renderer/rib/declarations.h"

namespace gonio {

// One parameter after typing: its declaration (decl.name is the bare name) and values. Numbers
// stay double, so that integer options (seeds, photon counts) survive exactly.
struct TypedParam {
    ParamDecl decl;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    // Typed by the standard table (standard_options.h): a parameter renderers know, which gonio
    // may accept without using (Option "limits" "gridsize"), so leaving it unread is a note,
    // not a warning.
    bool standard = false;
};

class ParamDict {
  public:
    // Adds `param`, given at `loc`; an entry of the same name is replaced (a later request
    // overrides an earlier one).
    void Set(TypedParam param, const FileLoc& loc);

    // The entry `name` (its bare name), marked as read; nullptr if there is none.
    const TypedParam* Find(const std::string& name) const;
    // Where the entry `name` was given (not a read); an empty location if there is none.
    FileLoc Location(const std::string& name) const;
    // Where the first entry was given, for messages about the request as a whole.
    FileLoc FirstLocation() const { return entries_.empty() ? FileLoc{} : entries_.front().loc; }
    // The first value of the numeric entry `name`; `fallback` if there is none.
    double GetNumber(const std::string& name, double fallback) const;
    float GetFloat(const std::string& name, float fallback) const {
        return static_cast<float>(GetNumber(name, fallback));
    }
    int GetInt(const std::string& name, int fallback) const {
        return static_cast<int>(GetNumber(name, fallback));
    }
    // The first value of the string entry `name`; `fallback` if there is none.
    std::string GetString(const std::string& name, const std::string& fallback) const;
    bool Has(const std::string& name) const { return Find(name) != nullptr; }
    // Marks `name` as read by a reader outside the frame's stages (the RIB front end follows
    // the archive path itself), so that it is not reported as unused.
    void MarkRead(const std::string& name) const { Find(name); }
    bool Empty() const { return entries_.empty(); }

    // Warnings (notes for standard parameters), at their RIB locations, for the entries nobody
    // read: `owner` names the request
    // ("Option \"trace\""). Copies of a dictionary share the marks (an Attribute read by any
    // shape counts as read), and a location is reported once, however many copies hold it.
    void ReportUnused(const std::string& owner, Diagnostics& diagnostics) const;

  private:
    struct Entry {
        TypedParam param;
        FileLoc loc;
        std::shared_ptr<std::atomic<bool>> read;
    };
    const Entry* FindEntry(const std::string& name) const;

    std::vector<Entry> entries_;
};

}  // namespace gonio
