#include "ui/script.h"

#include <charconv>
#include <cmath>
#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "scene/node_kinds.h"
#include "ui/panels.h"
#include "ui/placement.h"
#include "ui/transform_handles.h"
#include "ui/view_camera.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

struct CommandSpec {
    std::string_view name;
    int minArgs;
    int maxArgs;
    std::string_view usage;
};

constexpr CommandSpec kCommands[] = {
    {"select", 1, 1, "select <node path>|none"},
    {"set", 2, 2, "set <field or JSON path> <value>"},
    {"add", 1, 3, "add <kind> [under <node path>]"},
    {"wrap", 1, 1, "wrap <kind>"},
    {"place", 1, 1, "place <kind>"},
    {"duplicate", 0, 0, "duplicate"},
    {"delete", 0, 0, "delete"},
    {"rename", 1, 1, "rename <name>"},
    {"move", 2, 2, "move <new parent path> <index>"},
    {"undo", 0, 0, "undo"},
    {"redo", 0, 0, "redo"},
    {"backend", 1, 1, "backend cpu|gl"},
    {"compare", 1, 1, "compare off|side|diff"},
    {"heat", 1, 1, "heat on|off"},
    {"panel", 1, 1, "panel node|materials|lights|render|environment|library"},
    {"camera", 3, 3, "camera <azimuth> <elevation> <distance>"},
    {"orbit", 2, 2, "orbit <azimuth step> <elevation step>"},
    {"pick", 2, 2, "pick <x> <y>"},
    {"hide", 1, 1, "hide on|off"},
    {"solo", 1, 1, "solo on|off"},
    {"handles", 1, 1, "handles move|rotate|scale"},
    {"drag", 2, 3, "drag x|y|z <pixels> [snap]"},
    {"view", 1, 1, "view front|back|right|left|top|bottom|all|selected"},
    {"wait", 1, 1, "wait <frames>|idle"},
    {"screenshot", 1, 1, "screenshot <file.png>"},
    {"save", 1, 1, "save <file.json>"},
    {"open", 1, 1, "open <file.json>"},
    {"autosave", 0, 0, "autosave"},
    {"restore", 0, 0, "restore"},
    {"quit", 0, 1, "quit [discard]"},
    {"polynomial", 1, 4,
     "polynomial open|close|run|add, polynomial equations <text>, polynomial order <name>, "
     "polynomial range <parameter> <from> <to>, polynomial sheet <thickness>"},
};

const CommandSpec* findCommand(std::string_view name) {
    for (const CommandSpec& spec : kCommands) {
        if (spec.name == name) return &spec;
    }
    return nullptr;
}

// The blanks between words, and around a line: one set for both, so a line
// that trims to something always has a first word (a lone vertical tab was
// kept by the trim and then split into no words at all).
constexpr std::string_view kBlanks = " \t\r\v\f";

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    for (size_t begin = text.find_first_not_of(kBlanks); begin != std::string_view::npos;
         begin = text.find_first_not_of(kBlanks, begin)) {
        size_t end = std::min(text.find_first_of(kBlanks, begin), text.size());
        out.emplace_back(text.substr(begin, end - begin));
        begin = end;
    }
    return out;
}

std::string_view trim(std::string_view s) {
    size_t begin = s.find_first_not_of(kBlanks);
    if (begin == std::string_view::npos) return {};
    size_t end = s.find_last_not_of(kBlanks);
    return s.substr(begin, end - begin + 1);
}

bool parseNumber(const std::string& text, double& out) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

// A value as JSON: JSON text as it is ("[1, 2, 3]", "0.5", "true", "\"red\""),
// three bare numbers as an array ("1 2 3"), anything else as a string ("red").
nlohmann::ordered_json parseValue(const std::string& text) {
    try {
        return nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception&) {
    }
    std::vector<std::string> parts = words(text);
    if (parts.size() == 3) {
        nlohmann::ordered_json array = nlohmann::ordered_json::array();
        double v = 0;
        for (const std::string& part : parts) {
            if (!parseNumber(part, v)) return text;
            array.push_back(v);
        }
        return array;
    }
    return text;
}

std::string joined(const std::vector<std::string>& problems) {
    std::string text;
    for (const std::string& p : problems) text += (text.empty() ? "" : "; ") + p;
    return text;
}

std::string knownKinds() {
    std::string list;
    for (const scene::KindSpec& k : scene::allKinds()) list += (list.empty() ? "" : ", ") + std::string(k.name);
    return list;
}

}  // namespace

std::vector<ScriptCommand> parseScript(std::string_view text, const std::string& source) {
    std::vector<ScriptCommand> commands;
    int lineNumber = 0;
    while (!text.empty() || lineNumber == 0) {
        size_t end = text.find('\n');
        std::string_view line = trim(text.substr(0, end));
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
        ++lineNumber;
        if (line.empty() || line.front() == '#') {
            if (text.empty()) break;
            continue;
        }
        auto fail = [&](const std::string& reason) {
            throw std::runtime_error(source + ":" + std::to_string(lineNumber) + ": " + reason);
        };
        // `fails <command>`: the same command, expected to fail
        constexpr std::string_view kFails = "fails";
        bool expectFailure = line.starts_with(kFails) && (line.size() == kFails.size() || line[kFails.size()] == ' ' ||
                                                          line[kFails.size()] == '\t');
        if (expectFailure) {
            line = trim(line.substr(kFails.size()));
            if (line.empty()) fail("fails needs a command (usage: fails <command> ...)");
        }
        std::vector<std::string> parts = words(line);
        ScriptCommand command{lineNumber, parts.front(), {parts.begin() + 1, parts.end()}, expectFailure};
        const CommandSpec* spec = findCommand(command.name);
        if (!spec) {
            std::string list;
            for (const CommandSpec& s : kCommands) list += (list.empty() ? "" : ", ") + std::string(s.name);
            fail("unknown command \"" + command.name + "\" (known: " + list + ")");
        }
        bool keepsRest = command.name == "set" || (command.name == "polynomial" && !command.args.empty() &&
                                                   command.args[0] == "equations");
        if (keepsRest && command.args.size() >= 2) {
            // the value is the rest of the line, spaces included
            std::string_view rest = trim(line.substr(line.find(command.args[0], command.name.size()) + command.args[0].size()));
            command.args = {command.args[0], std::string(rest)};
        }
        int count = static_cast<int>(command.args.size());
        if (count < spec->minArgs || count > spec->maxArgs) {
            fail("wrong number of arguments (usage: " + std::string(spec->usage) + ")");
        }
        commands.push_back(std::move(command));
        if (text.empty()) break;
    }
    return commands;
}

ScriptStatus ScriptRunner::refuse(const ScriptCommand& command, UiState& ui, const Problems& problems) {
    if (command.expectFailure) reportProblems(ui, problems);
    return fail(command, joined(problems));
}

ScriptRunner::ScriptRunner(std::vector<ScriptCommand> commands, std::string source)
    : commands_(std::move(commands)), source_(std::move(source)) {}

ScriptStatus ScriptRunner::fail(const ScriptCommand& command, const std::string& reason) {
    error_ = source_ + ":" + std::to_string(command.line) + ": " + command.name + ": " + reason;
    return ScriptStatus::Failed;
}

bool ScriptRunner::waitIdle(const ScriptCommand& command, ScriptHost& host) {
    if (!waitingIdle_) {
        waitingIdle_ = true;
        waitStart_ = std::chrono::steady_clock::now();
    }
    if (!host.idle()) {
        return false;
    }
    waitingIdle_ = false;
    return true;
}

ScriptStatus ScriptRunner::step(Editor& editor, UiState& ui, ScriptHost& host) {
    if (!error_.empty()) return ScriptStatus::Failed;
    if (next_ >= commands_.size()) return ScriptStatus::Finished;
    const ScriptCommand& command = commands_[next_];
    ScriptStatus status = run(command, editor, ui, host);
    if (command.expectFailure && status != ScriptStatus::Running) {
        if (status != ScriptStatus::Failed) {
            error_.clear();
            return fail(command, "succeeded, but the script expects it to fail");
        }
        // shown as the user would see it; the script goes on
        ui.info(error_ + " (expected)");
        error_.clear();
        ++next_;
        status = ScriptStatus::Finished;
    }
    if (status == ScriptStatus::Failed) return status;
    if (waitingIdle_ && std::chrono::steady_clock::now() - waitStart_ > idleTimeout) {
        return fail(command, "still busy after " + std::to_string(idleTimeout.count()) +
                                 " s (renders, shader compiles or thumbnails did not finish)");
    }
    return next_ >= commands_.size() && status != ScriptStatus::Running ? ScriptStatus::Finished
                                                                        : ScriptStatus::Running;
}

// Returns Running while the command waits (next_ unchanged), otherwise advances.
ScriptStatus ScriptRunner::run(const ScriptCommand& c, Editor& editor, UiState& ui, ScriptHost& host) {
    const std::vector<std::string>& a = c.args;
    auto done = [&](const Problems& problems = {}) {
        if (!problems.empty()) return refuse(c, ui, problems);
        ++next_;
        return ScriptStatus::Finished;
    };
    auto needSelection = [&]() -> const NodePath* { return editor.selection() ? &*editor.selection() : nullptr; };
    auto kindArg = [&](const std::string& name) -> const scene::KindSpec* { return scene::findKind(name); };

    if (c.name == "select") {
        if (a[0] == "none") {
            editor.select(std::nullopt);
            return done();
        }
        std::optional<NodePath> path = parseNodePath(a[0]);
        if (!path) return fail(c, "\"" + a[0] + "\" is not a node path (write e.g. root.children[0])");
        if (!findNode(editor.scene().root, *path)) return fail(c, a[0] + ": no such node");
        editor.select(path);
        return done();
    }
    if (c.name == "set") {
        bool sceneLevel = a[0].find_first_of(".[") != std::string::npos;
        if (sceneLevel) return done(editor.setJsonValue(a[0], parseValue(a[1])));
        const NodePath* selected = needSelection();
        if (!selected) return fail(c, "no node selected (use select <node path>, or a JSON path such as render.aa)");
        return done(editor.setJsonValue(formatNodePath(*selected) + "." + a[0], parseValue(a[1])));
    }
    if (c.name == "add" || c.name == "wrap" || c.name == "place") {
        const scene::KindSpec* kind = kindArg(a[0]);
        if (!kind) return fail(c, "unknown node kind \"" + a[0] + "\" (known: " + knownKinds() + ")");
        if (c.name == "place") return done(addPlaced(editor, kind->kind));
        if (c.name == "wrap") {
            const NodePath* selected = needSelection();
            if (!selected) return fail(c, "no node selected");
            return done(editor.wrap(*selected, kind->kind));
        }
        std::optional<NodePath> under;
        if (a.size() > 1) {
            if (a.size() != 3 || a[1] != "under") return fail(c, "usage: add <kind> [under <node path>]");
            under = parseNodePath(a[2]);
            if (!under) return fail(c, "\"" + a[2] + "\" is not a node path");
        }
        return done(editor.add(kind->kind, under));
    }
    if (c.name == "duplicate" || c.name == "delete" || c.name == "rename" || c.name == "move") {
        const NodePath* selected = needSelection();
        if (!selected) return fail(c, "no node selected");
        NodePath path = *selected;
        if (c.name == "duplicate") return done(duplicatePlaced(editor, path));
        if (c.name == "delete") return done(editor.remove(path));
        if (c.name == "rename") return done(editor.rename(path, a[0]));
        std::optional<NodePath> parent = parseNodePath(a[0]);
        double index = 0;
        if (!parent) return fail(c, "\"" + a[0] + "\" is not a node path");
        if (!parseNumber(a[1], index) || index < 0 || index != std::floor(index)) {
            return fail(c, "index must be a whole number >= 0 (got " + a[1] + ")");
        }
        return done(editor.move(path, *parent, static_cast<int>(index)));
    }
    if (c.name == "undo") return editor.undo() ? done() : fail(c, "nothing to undo");
    if (c.name == "redo") return editor.redo() ? done() : fail(c, "nothing to redo");
    if (c.name == "backend") {
        if (a[0] != "cpu" && a[0] != "gl") return fail(c, "must be cpu or gl (got " + a[0] + ")");
        ui.backend = a[0] == "cpu" ? ViewBackend::Cpu : ViewBackend::Gl;
        return done();
    }
    if (c.name == "compare") {
        if (a[0] == "off") ui.compare = CompareMode::Off;
        else if (a[0] == "side") ui.compare = CompareMode::SideBySide;
        else if (a[0] == "diff") ui.compare = CompareMode::Difference;
        else return fail(c, "must be off, side or diff (got " + a[0] + ")");
        return done();
    }
    if (c.name == "heat") {
        if (a[0] != "on" && a[0] != "off") return fail(c, "must be on or off (got " + a[0] + ")");
        ui.stepHeat = a[0] == "on";
        return done();
    }
    if (c.name == "panel") {
        for (size_t i = 0; i < std::size(kInspectorTabNames); ++i) {
            if (a[0] == kInspectorTabNames[i]) {
                ui.showTab = static_cast<InspectorTab>(i);
                return done();
            }
        }
        return fail(c, "must be node, materials, lights, render, environment or library (got " + a[0] + ")");
    }
    if (c.name == "camera") {
        double v[3];
        for (int i = 0; i < 3; ++i) {
            if (!parseNumber(a[static_cast<size_t>(i)], v[i])) return fail(c, "\"" + a[static_cast<size_t>(i)] + "\" is not a number");
        }
        scene::Camera camera = editor.scene().camera;
        camera.azimuth = v[0];
        camera.elevation = v[1];
        camera.distance = v[2];
        return done(editor.setView(camera));
    }
    if (c.name == "pick") {
        double v[2];
        for (int i = 0; i < 2; ++i) {
            if (!parseNumber(a[static_cast<size_t>(i)], v[i]) || v[i] < 0 || v[i] > 1) {
                return fail(c, "\"" + a[static_cast<size_t>(i)] + "\" is not a fraction of the view from 0 to 1");
            }
        }
        auto [width, height] = host.viewSize();
        if (width <= 0 || height <= 0) std::tie(width, height) = std::pair{editor.scene().render.width, editor.scene().render.height};
        selectPicked(editor, pickView(editor.scene(), width, height, v[0] * width, v[1] * height));
        ui.showTab = InspectorTab::Node;
        return done();
    }
    if (c.name == "hide" || c.name == "solo") {
        if (a[0] != "on" && a[0] != "off") return fail(c, "must be on or off (got " + a[0] + ")");
        if (!editor.selection()) return fail(c, "nothing is selected");
        const NodePath& path = *editor.selection();
        return done(c.name == "hide" ? editor.setHidden(path, a[0] == "on") : editor.setSolo(path, a[0] == "on"));
    }
    if (c.name == "handles") {
        std::optional<HandleMode> mode = handleModeNamed(a[0]);
        if (!mode) return fail(c, "must be move, rotate or scale (got " + a[0] + ")");
        ui.handles = *mode;
        return done();
    }
    if (c.name == "drag") {
        double pixels = 0;
        int axis = a[0] == "x" ? 0 : a[0] == "y" ? 1 : a[0] == "z" ? 2 : -1;
        if (axis < 0) return fail(c, "the axis must be x, y or z (got " + a[0] + ")");
        if (!parseNumber(a[1], pixels) || std::abs(pixels) > 1e4) return fail(c, "\"" + a[1] + "\" is not a number of pixels up to 10000");
        if (a.size() == 3 && a[2] != "snap") return fail(c, "the third word can only be snap (got " + a[2] + ")");
        if (!editor.selection()) return fail(c, "nothing is selected");
        auto [width, height] = host.viewSize();
        if (width <= 0 || height <= 0) std::tie(width, height) = std::pair{editor.scene().render.width, editor.scene().render.height};
        std::optional<HandleLayout> layout = handleLayout(editor.scene(), *editor.selection(), ui.handles, width, height);
        std::optional<HandleGrip> grip = layout ? handleGrip(*layout, ui.handles, axis) : std::nullopt;
        if (!grip) return fail(c, "the " + a[0] + " handle is not in view");
        // pressed, moved in steps as a hand does, released: one undo step
        HandleDrag drag;
        if (!drag.begin(editor, ui.handles, width, height, grip->point)) return fail(c, "the " + a[0] + " handle is covered by another");
        constexpr int kSteps = 8;
        Problems problems;
        for (int i = 1; i <= kSteps && problems.empty(); ++i) {
            problems = drag.update(editor, grip->point + (pixels * i / kSteps) * grip->direction, a.size() == 3);
        }
        drag.end(editor);
        return done(problems);
    }
    if (c.name == "orbit") {
        double v[2];
        for (int i = 0; i < 2; ++i) {
            if (!parseNumber(a[static_cast<size_t>(i)], v[i])) return fail(c, "\"" + a[static_cast<size_t>(i)] + "\" is not a number");
        }
        return done(editor.setView(orbited(editor.scene().camera, editor.scene().environment, v[0], v[1])));
    }
    if (c.name == "view") {
        if (a[0] == "all") return done(editor.setView(frameAllCamera(editor.scene())));
        if (a[0] == "selected") {
            if (!editor.selection()) return fail(c, "nothing is selected");
            std::optional<scene::Camera> framed = frameSelectedCamera(editor.scene(), *editor.selection());
            if (!framed) return fail(c, formatNodePath(*editor.selection()) + " is unbounded: nothing to frame");
            return done(editor.setView(*framed));
        }
        std::optional<ViewPreset> preset = viewPresetNamed(a[0]);
        if (!preset) return fail(c, "must be front, back, right, left, top, bottom, all or selected (got " + a[0] + ")");
        return done(editor.setView(presetCamera(editor.scene().camera, *preset)));
    }
    if (c.name == "wait") {
        if (a[0] == "idle") {
            if (!waitIdle(c, host)) return ScriptStatus::Running;
            return done();
        }
        double frames = 0;
        if (!parseNumber(a[0], frames) || frames < 0 || frames != std::floor(frames)) {
            return fail(c, "must be a whole number of frames or idle (got " + a[0] + ")");
        }
        if (framesLeft_ < 0) framesLeft_ = static_cast<int>(frames);
        if (framesLeft_-- > 0) return ScriptStatus::Running;
        framesLeft_ = -1;
        return done();
    }
    if (c.name == "screenshot") {
        if (!waitIdle(c, host)) return ScriptStatus::Running;
        std::string problem = host.requestScreenshot(a[0]);
        return problem.empty() ? done() : fail(c, problem);
    }
    if (c.name == "save" || c.name == "open") {
        std::string problem = c.name == "save" ? host.save(a[0]) : host.open(a[0]);
        return problem.empty() ? done() : fail(c, problem);
    }
    if (c.name == "autosave" || c.name == "restore") {
        std::string problem = c.name == "autosave" ? host.autosave() : host.restoreAutosave();
        return problem.empty() ? done() : fail(c, problem);
    }
    if (c.name == "quit") {
        if (a.size() == 1 && a[0] != "discard") return fail(c, "usage: quit [discard]");
        if (a.empty() && editor.dirty()) {
            return fail(c, "the scene has unsaved changes (save it first, or use quit discard)");
        }
        host.quit();
        return done();
    }
    if (c.name == "polynomial") return runPolynomial(c, editor, ui, host);
    // parseScript admits only the commands handled above
    return fail(c, "no handler for this command (a bug: please report it)");
}

ScriptStatus ScriptRunner::runPolynomial(const ScriptCommand& c, Editor& editor, UiState& ui, ScriptHost& host) {
    PolynomialPanelState& panel = host.polynomialPanel();
    const std::vector<std::string>& a = c.args;
    auto done = [&](const Problems& problems = {}) {
        if (!problems.empty()) return refuse(c, ui, problems);
        ++next_;
        return ScriptStatus::Finished;
    };
    const std::string& action = a[0];
    auto arguments = [&](size_t count) { return a.size() == count + 1; };
    if ((action == "open" || action == "close") && arguments(0)) {
        panel.open = action == "open";
        return done();
    }
    if (action == "equations" && arguments(1)) {
        panel.request.equations = a[1];
        return done();
    }
    if (action == "order" && arguments(1)) {
        std::optional<algebra::EliminationOrder> order = algebra::eliminationOrderFromName(a[1]);
        if (!order) return fail(c, "unknown order \"" + a[1] + "\" (see implicitize --help)");
        panel.request.order = *order;
        return done();
    }
    if (action == "sheet" && arguments(1)) {
        double thickness = 0;
        if (!parseNumber(a[1], thickness) || thickness < 0) return fail(c, "the sheet thickness must be a number >= 0");
        panel.sheetThickness = thickness;
        return done();
    }
    if (action == "range" && arguments(3)) {
        readParameters(panel);
        if (!panel.problem.empty()) return fail(c, panel.problem);
        double from = 0, to = 0;
        if (!parseNumber(a[2], from) || !parseNumber(a[3], to)) return fail(c, "the range must be two numbers");
        for (ParameterRange& range : panel.ranges) {
            if (range.name != a[1]) continue;
            range.min = from;
            range.max = to;
            return done();
        }
        return fail(c, "the equations have no parameter \"" + a[1] + "\"");
    }
    if (action == "run" && arguments(0)) {
        if (!polynomialRunning_) {
            readParameters(panel);
            if (!panel.problem.empty()) return fail(c, panel.problem);
            ::sdfwb::ui::runPolynomial(panel);
            polynomialRunning_ = true;
        }
        if (panel.job.running()) return ScriptStatus::Running;
        polynomialRunning_ = false;
        PolynomialOutcome outcome = panel.job.outcome().value();
        return outcome.ok ? done() : fail(c, outcome.message);
    }
    if (action == "add" && arguments(0)) {
        std::optional<PolynomialOutcome> outcome = panel.job.outcome();
        if (!outcome || !outcome->isSurface()) return fail(c, "no surface to add (run a surface's equations first)");
        return done(addPolynomialNode(editor, ui, *outcome, panel.sheetThickness));
    }
    return fail(c, "usage: " + std::string(findCommand("polynomial")->usage));
}

std::string screenshotScript(const std::string& output, int frames) {
    return "wait " + std::to_string(frames) + "\nscreenshot " + output + "\nquit discard\n";
}

}  // namespace sdfwb::ui
