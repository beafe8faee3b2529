#pragma once
// The request table: one row per RIB request with its name, its positional-argument signature
// and a function that calls the matching RiTarget method. MatchRequest checks a request's values
// against the row's signature and, if they fit, hands the row's function typed accessors.
//
// Signature letters, one per positional argument (alternatives separated by '|'):
//   f float   i integer   s string   h handle (integer or string)   B basis (name or 16 numbers)
//   F array of floats   I array of integers   S array of strings   c a colour (ncomps floats)
//   * anything (the request is ignored)
// A signature of floats only (or a colour) may also arrive as one bracketed array, and a scalar
// may arrive as a one-element array.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/file_loc.h"
#include "renderer/rib/param_list.h"
#include "renderer/rib/request_values.h"
#include "renderer/rib/ri_target.h"

namespace gonio {

// The few requests the parser acts on itself, besides passing them on.
class ParserHooks {
  public:
    virtual ~ParserHooks() = default;
    virtual void ReadArchive(const std::string& name, const FileLoc& loc) = 0;
    // Passes a Procedural on to the target with a reader for the RIB it stands for.
    virtual void Procedural(const std::string& name, const std::vector<std::string>& args,
                            const std::vector<float>& bound6, const FileLoc& loc) = 0;
    virtual void OptionSeen(const std::string& name, const ParamList& params) = 0;
    virtual void ColorSamplesSeen(int ncomps) = 0;
    // An extension request that has no RiTarget method: warns once and ignores it.
    virtual void Ignore(const char* request, const FileLoc& loc) = 0;
    // A request whose meaning the parser cannot honour by ignoring it (inline archives,
    // conditionals): an error.
    virtual void Unsupported(const char* request, const FileLoc& loc) = 0;
};

class RequestArgs;
using RequestCall = void (*)(const RequestArgs& args, RiTarget& target, ParserHooks& hooks);

struct RequestRule {
    const char* name;
    const char* signature;
    bool takesParams;  // a parameter list may follow the positional arguments
    RequestCall call;
};

// Typed access to the positional arguments and the parameter list of a matched request.
class RequestArgs {
  public:
    float F(int k) const;
    int I(int k) const;
    const std::string& S(int k) const;
    RtHandle H(int k) const;
    RtBasis B(int k) const;
    std::vector<float> FA(int k) const;
    std::vector<int> IA(int k) const;
    std::vector<std::string> SA(int k) const;
    std::vector<float> AllFloats() const;  // every positional number, for colours and bounds
    RtMatrix Matrix() const;               // the 16 positional numbers
    const char* Name() const { return name_; }
    int Alternative() const { return alternative_; }
    int Count() const { return static_cast<int>(slots_.size()); }
    const ParamList& Params() const { return params_; }
    const FileLoc& Loc() const { return loc_; }

  private:
    friend class RequestMatcher;
    struct Slot {
        const RibValue* value;
        std::size_t element;  // within an array value
    };
    double Number(int k) const;

    const RequestValues* values_ = nullptr;
    std::vector<Slot> slots_;
    ParamList params_;
    FileLoc loc_;
    const char* name_ = "";
    int alternative_ = 0;
};

// The row for a request name, or nullptr if there is no such request.
const RequestRule* FindRequest(std::string_view name);

// Every row, in table order (for documentation and the fuzzing dictionary).
const std::vector<RequestRule>& AllRequests();

struct MatchError {
    int line = 0;
    int column = 0;
    std::string message;
};

// Checks `values` against `rule`; on success fills `args` and returns true, else fills `error`.
// `ncomps` is the current number of colour components (ColorSamples). On success the numeric
// arrays of the parameter list have moved out of `values` into `args`.
bool MatchRequest(const RequestRule& rule, RequestValues& values, int ncomps, const FileLoc& loc,
                  RequestArgs* args, MatchError* error);

}  // namespace gonio
