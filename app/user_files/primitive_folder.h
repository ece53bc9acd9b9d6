#pragma once
// The primitive library on disk: one JSON file per entry in a folder
// (configDirectory()/primitives). The folder is listed once and after each
// change made here (or refresh()), never per frame.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/primitive_library.h"

namespace sdfwb::app {

class PrimitiveFolder final : public ui::PrimitiveLibrary {
public:
    // The user's library (configDirectory()/primitives), or `folder`.
    PrimitiveFolder();
    explicit PrimitiveFolder(std::filesystem::path folder);

    const std::vector<std::string>& entries() override;
    void refresh() override;
    void save(const std::string& name, const scene::Node& node) override;
    scene::Node load(const std::string& name) const override;
    void remove(const std::string& name) override;
    const std::optional<std::string>& removed() const override { return removedName_; }
    void restoreRemoved() override;

private:
    std::filesystem::path fileOf(const std::string& name) const;

    std::filesystem::path folder_;
    std::optional<std::vector<std::string>> entries_;
    std::optional<std::string> removedName_;
    std::string removedText_;  // what restoreRemoved() writes back
};

}  // namespace sdfwb::app
