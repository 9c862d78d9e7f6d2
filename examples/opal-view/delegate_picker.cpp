#include "examples/opal-view/delegate_picker.h"

#include <imgui.h>

namespace opal::view {
namespace {

// One row per delegate; the type of the one clicked that is not in use.
std::optional<std::string> choiceTable(const std::vector<DelegateChoice>& choices) {
    std::optional<std::string> chosen;
    if (!ImGui::BeginTable("##delegates", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return chosen;
    ImGui::TableSetupColumn("delegate");
    ImGui::TableSetupColumn("type");
    ImGui::TableSetupColumn("priority");
    ImGui::TableHeadersRow();
    for (const DelegateChoice& choice : choices) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushID(choice.typeName.c_str());
        if (ImGui::RadioButton(choice.displayName.c_str(), choice.current) && !choice.current) chosen = choice.typeName;
        ImGui::PopID();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(choice.typeName.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%d", choice.priority);
    }
    ImGui::EndTable();
    return chosen;
}

}  // namespace

std::optional<std::string> drawDelegatePicker(const std::vector<DelegateChoice>& choices,
                                              const std::vector<std::string>& skipped, bool& open) {
    if (!open) return std::nullopt;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 470.0f, 30.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(460.0f, 0.0f), ImGuiCond_FirstUseEver);
    std::optional<std::string> chosen;
    if (ImGui::Begin("Render delegates", &open)) {
        ImGui::TextDisabled("Found by the plugin registry, by priority");
        chosen = choiceTable(choices);
        ImGui::Separator();
        if (skipped.empty()) ImGui::TextDisabled("Skipped: none");
        else ImGui::TextUnformatted("Skipped:");
        for (const std::string& problem : skipped) ImGui::TextWrapped("%s", problem.c_str());
    }
    ImGui::End();
    return chosen;
}

}  // namespace opal::view
