#include "renderer/scene/param_dict.h"

namespace gonio {

void ParamDict::Set(TypedParam param, const FileLoc& loc) {
    Entry entry{std::move(param), loc, std::make_shared<std::atomic<bool>>(false)};
    for (Entry& old : entries_) {
        if (old.param.decl.name == entry.param.decl.name) {
            old = std::move(entry);
            return;
        }
    }
    entries_.push_back(std::move(entry));
}

const ParamDict::Entry* ParamDict::FindEntry(const std::string& name) const {
    for (const Entry& entry : entries_) {
        if (entry.param.decl.name != name) continue;
        entry.read->store(true, std::memory_order_relaxed);
        return &entry;
    }
    return nullptr;
}

const TypedParam* ParamDict::Find(const std::string& name) const {
    const Entry* entry = FindEntry(name);
    return entry ? &entry->param : nullptr;
}

FileLoc ParamDict::Location(const std::string& name) const {
    for (const Entry& entry : entries_)
        if (entry.param.decl.name == name) return entry.loc;
    return {};
}

double ParamDict::GetNumber(const std::string& name, double fallback) const {
    const TypedParam* param = Find(name);
    return param && !param->numbers.empty() ? param->numbers[0] : fallback;
}

std::string ParamDict::GetString(const std::string& name, const std::string& fallback) const {
    const TypedParam* param = Find(name);
    return param && !param->strings.empty() ? param->strings[0] : fallback;
}

void ParamDict::ReportUnused(const std::string& owner, Diagnostics& diagnostics) const {
    for (const Entry& entry : entries_) {
        if (entry.read->load(std::memory_order_relaxed)) continue;
        const std::string& name = entry.param.decl.name;
        const std::string key = "unused " + entry.loc.ToString() + " " + owner + " " + name;
        const std::string message =
            owner + " parameter \"" + name + "\" had no effect on this frame";
        if (entry.param.standard)
            diagnostics.NoteOnce(key, entry.loc, message);
        else
            diagnostics.WarningOnce(key, entry.loc, message);
    }
}

}  // namespace gonio
