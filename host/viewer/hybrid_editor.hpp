// SPDX-License-Identifier: Apache-2.0
#pragma once
// The hybrid editor: the panel's "Formula sequence" section for a formula scene (the formulas it
// iterates, their order and repeats) and "Save as". An edit makes a new scene that the render
// thread builds as it builds a reloaded one: the old scene and its image stay until the new kernel
// compiles, and a build that fails keeps them. Private to fgr_viewer.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "scene/formulas/formulas.hpp"
#include "scene/scene.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/replay.hpp"
#include "viewer/scene_set.hpp"

namespace fgr::viewer {

// What the hybrid editor asks of the viewer.
struct HybridHost {
    std::function<void(ReloadRequest)> build;  // on the render thread, before it replaces anything
    // The built edit takes the place of scene `index`.
    std::function<void(size_t index, std::shared_ptr<const Scene> scene)> adopt_scene;
    // Shows why an edit's build was refused (summary, compiler log).
    std::function<void(std::string summary, std::string log)> show_refused;
    std::function<void(std::string)> add_message;
};

class HybridEditor {
public:
    // Saved scenes go to `output_dir`.
    HybridEditor(SceneSet& scenes, std::filesystem::path output_dir, HybridHost host);

    // The sequence of scene `index` when it is a formula scene: read from its file once, then
    // what the editor made of it. Null for other scenes and unreadable files.
    const FormulaScene* formula_of(size_t index);

    void draw_section();
    // Takes the render thread's verdict on the pending edit; false when `result` is not about it.
    bool adopt_edit(const ReloadResult& result);
    // hybrid_add, hybrid_remove, hybrid_move, hybrid_repeat and hybrid_save; others are not the
    // editor's.
    void apply_replay_event(const ReplayEvent& event);
    int edits_adopted() const { return edits_adopted_; }

private:
    void draw_slot(const FormulaScene& formula, size_t slot);
    // Makes the edit of the current formula scene; the render thread builds the result, which
    // replaces the scene once it compiles (adopt_edit).
    void edit(const std::function<FormulaScene(FormulaScene)>& change);
    // Writes the current formula scene, as edited and with the panel's values, as
    // <output dir>/<id>.formula.json under the id `id`.
    void save(const std::string& id);

    SceneSet& scenes_;
    std::filesystem::path output_dir_;
    HybridHost host_;
    // Each formula scene's sequence, with the scene version it belongs to: a reload makes it stale.
    struct FormulaSource {
        std::shared_ptr<const Scene> scene;
        std::optional<FormulaScene> formula;  // none: not a formula scene, or unreadable
    };
    std::map<size_t, FormulaSource> formula_sources_;
    // The edit the render thread is building: the new scene and its sequence.
    struct PendingEdit {
        std::shared_ptr<const Scene> scene;
        FormulaScene formula;
    };
    std::optional<PendingEdit> pending_;
    std::string error_;    // the last edit that was refused, one line
    std::string save_id_;  // the "save as" id
    int edits_adopted_ = 0;
};

}  // namespace fgr::viewer
