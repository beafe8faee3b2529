#pragma once
// RenderMan search paths (`Option "searchpath" "shader" | "texture" | "archive"`): a
// colon-separated list of folders in which '&' stands for the previous path and '@' for the
// renderer's default one. Shared by the RIB front end (archives), the shading system (shaders)
// and the renderer (textures, .grd files).

#include <string>
#include <vector>

namespace gonio {

// The folders of `text`, with '&' replaced by `previous` and '@' by `standard`.
std::vector<std::string> ExpandSearchPath(const std::string& text,
                                          const std::vector<std::string>& previous,
                                          const std::vector<std::string>& standard);

// The text of a new search path whose '&' entries stand for `previous`, the text in effect
// before it ("@" when none was set), so that a later path can in turn refer to this one.
std::string SubstitutePreviousPath(const std::string& text, const std::string& previous);

// Where `name` is: itself when absolute, else the first `folder/name` that exists; empty when
// there is none.
std::string FindOnSearchPath(const std::string& name, const std::vector<std::string>& folders);

}  // namespace gonio
