package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiInputTextFlags;
import imgui.type.ImString;
import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import org.robotrun.io.ScenarioWriter;
import org.robotrun.world.CellEditor;
import org.robotrun.world.CellEditor.NumberField;
import org.robotrun.world.CellEditor.Result;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Shape;
import org.robotrun.world.WorldObject;

/**
 * The cell editor's panel (the paper's section 3.6 and its Figure 10): the scenarios of the
 * workspace (one active), add a box, cylinder or STL mesh, and the selected object's name, kind,
 * parent, colour, pose and size in text fields. A field is applied on Enter or when it loses the
 * keyboard; a refused value shows one message naming the field and its range, and the field shows
 * the old value again. Undo and redo (Ctrl+Z, Ctrl+Y) go back and forth through cell edits.
 */
public final class CellEditorPanel {
  /** Picks an STL file (a file dialog once the window has one); empty when cancelled. */
  @FunctionalInterface
  public interface StlPicker {
    Optional<Path> pick();
  }

  private final CellEditor editor;
  private final Map<String, ImString> fields = new HashMap<>();
  private final Map<String, float[]> buttons = new HashMap<>();
  private final ImString stlPath = new ImString(512);
  private final ImString stlScale = new ImString("1", 32);
  private final ImString newScenario = new ImString(64);
  private final ImString savePath = new ImString(512);
  private StlPicker stlPicker;
  private String selected = "";
  private String message = "";
  private boolean messageIsError;
  /** When the last message came (nanoseconds of {@link #clock}). */
  private long messageNanos;
  private java.util.function.LongSupplier clock = System::nanoTime;
  /** How long the 3D view's strip shows a confirmation, and a refusal (the panel keeps both). */
  static final double STRIP_DONE_SECONDS = 5;
  static final double STRIP_ERROR_SECONDS = 15;
  private long shownRevision = -1;

  /** Whether edits are saved with a workspace (then the file row only exports a copy). */
  private boolean inWorkspace;

  public CellEditorPanel(CellEditor editor, Path saveTo) {
    this.editor = editor;
    savePath.set(saveTo == null ? "" : saveTo.toString());
  }

  /**
   * The editor of a workspace: every edit and the other scenarios are saved with it (autosave),
   * switching scenario opens the chosen one, and the file row exports a copy.
   */
  public CellEditorPanel inWorkspace() {
    inWorkspace = true;
    return this;
  }

  /** A file dialog for STL files (the workspace engineer's lwjgl-nfd); without one a path field is shown. */
  public void setStlPicker(StlPicker picker) {
    stlPicker = picker;
  }

  public CellEditor editor() {
    return editor;
  }

  public String selected() {
    return selected;
  }

  /** Selects an object (a click in the 3D view); "" selects nothing. */
  public void select(String name) {
    String now = name == null ? "" : name;
    if (!now.equals(selected)) {
      // a message about the object selected before no longer applies in the 3D view
      messageNanos = Long.MIN_VALUE / 2;
    }
    selected = now;
  }

  /** The last edit's message for a status line, "" when none. */
  public String message() {
    return message;
  }

  public boolean messageIsError() {
    return messageIsError;
  }

  /** The clock the strip's time-outs read (tests pass their own). */
  void setClock(java.util.function.LongSupplier nanos) {
    clock = nanos;
  }

  /**
   * The message the strip along the bottom of the 3D view shows now: the last edit's answer, a
   * confirmation for {@link #STRIP_DONE_SECONDS} and a refusal for {@link #STRIP_ERROR_SECONDS}
   * (or until the next edit or another selection), so nothing stays there once it no longer
   * applies; the panel's own line keeps the last message.
   */
  public Optional<String> stripMessage() {
    if (message.isEmpty()) {
      return Optional.empty();
    }
    double age = (clock.getAsLong() - messageNanos) / 1e9;
    return age < (messageIsError ? STRIP_ERROR_SECONDS : STRIP_DONE_SECONDS) ? Optional.of(message) : Optional.empty();
  }

  /** When the strip's message goes away ({@link #clock} nanoseconds), or {@link Long#MAX_VALUE} when none shows. */
  public long stripExpiresNanos() {
    if (stripMessage().isEmpty()) {
      return Long.MAX_VALUE;
    }
    return messageNanos + (long) ((messageIsError ? STRIP_ERROR_SECONDS : STRIP_DONE_SECONDS) * 1e9) + 1;
  }

  /** Applies an edit's result: remembers the message, forgets field texts so they show the model. */
  public void report(Result r) {
    messageNanos = clock.getAsLong();
    switch (r) {
      case Result.Done d -> {
        message = d.message();
        messageIsError = false;
      }
      case Result.Refused no -> {
        message = no.message();
        messageIsError = true;
      }
    }
    fields.clear();
  }

  public void undo() {
    report(editor.undo());
    keepSelection();
  }

  public void redo() {
    report(editor.redo());
    keepSelection();
  }

  private void keepSelection() {
    if (editor.world().find(selected).isEmpty()) {
      selected = "";
    }
  }

  /** Draws the panel into the current window. */
  public void drawContents() {
    if (editor.revision() != shownRevision) {
      shownRevision = editor.revision();
      fields.clear();
      keepSelection();
    }
    drawScenarios();
    drawRobotModels();
    ImGui.separator();
    if (ImGui.button("Add box")) {
      addAndSelect(editor.addBox());
    }
    remember("Add box");
    ImGui.sameLine();
    if (ImGui.button("Add cylinder")) {
      addAndSelect(editor.addCylinder());
    }
    drawStl();
    ImGui.separator();
    drawObjectList();
    if (!selected.isEmpty()) {
      drawSelected(editor.world().find(selected).orElseThrow());
    }
    ImGui.separator();
    if (ImGui.button("Undo") ) {
      undo();
    }
    ImGui.sameLine();
    if (ImGui.button("Redo")) {
      redo();
    }
    ImGui.sameLine();
    Txt.disabled("Ctrl+Z / Ctrl+Y");
    drawSave();
    if (!message.isEmpty()) {
      if (messageIsError) {
        ImGui.pushStyleColor(imgui.flag.ImGuiCol.Text, 1f, 0.45f, 0.35f, 1f);
      }
      Txt.wrapped(message);
      if (messageIsError) {
        ImGui.popStyleColor();
      }
    }
  }

  private void addAndSelect(Result r) {
    report(r);
    if (r instanceof Result.Done) {
      List<WorldObject> all = editor.world().objects();
      selected = all.get(all.size() - 1).name();
    }
  }

  /** One model choice per robot of the active scenario (only in a workspace: the cell is opened again). */
  private void drawRobotModels() {
    if (!inWorkspace) {
      return;
    }
    var robots = editor.active().robots();
    for (int i = 0; i < robots.size(); i++) {
      var r = robots.get(i);
      Txt.disabled("Robot " + r.name());
      ImGui.setNextItemWidth(-1);
      if (ImGui.beginCombo("##model" + i, modelName(r.modelId()))) {
        for (org.robotrun.io.RobotDefinitions.Entry e : org.robotrun.io.RobotDefinitions.library()) {
          if (ImGui.selectable(e.name() + "##m" + i + e.id(), e.id().equals(r.modelId()))) {
            report(editor.setRobotModel(i, e.id(), jointsFor(e.id(), r.initialJointsRad())));
          }
        }
        ImGui.endCombo();
      }
      if (ImGui.isItemHovered()) {
        Txt.tooltip("Choosing another model opens the cell again with it (the robot starts at its scenario joints,"
            + " or at HOME where those are outside the new model's limits). Your programs stay.");
      }
    }
  }

  private static String modelName(String id) {
    return org.robotrun.io.RobotDefinitions.library().stream().filter(e -> e.id().equals(id)).map(e -> e.name())
        .findFirst().orElse(id);
  }

  /** The robot's joints if the new model allows them, else HOME (pendant convention, rad). */
  private static List<Double> jointsFor(String modelId, List<Double> pendantRad) {
    org.robotrun.robot.RobotModel m = org.robotrun.io.RobotDefinitions.load(modelId);
    double[] p = pendantRad.stream().mapToDouble(Double::doubleValue).toArray();
    if (m.firstJointOutsideLimits(org.robotrun.robot.JointConvention.pendantToKinematic(m, p)) < 0) {
      return pendantRad;
    }
    return List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0);
  }

  private void drawScenarios() {
    var scenarios = editor.scenarios();
    Txt.disabled("Scenario");
    ImGui.setNextItemWidth(-1);
    if (ImGui.beginCombo("##scenario", shown(editor.active().name()))) {
      for (int i = 0; i < scenarios.size(); i++) {
        if (ImGui.selectable(shown(scenarios.get(i).name()) + "##sc" + i, i == editor.activeIndex())) {
          report(editor.activate(i));
        }
      }
      ImGui.endCombo();
    }
    if (inWorkspace && ImGui.isItemHovered()) {
      Txt.tooltip("Choosing another scenario opens it: its robots, frames, parts, camera and task replace the cell"
          + " (this one is kept as it is now). Your programs stay.");
    }
    ImGui.setNextItemWidth(ImGui.getContentRegionAvailX() * 0.55f);
    boolean enter = ImGui.inputTextWithHint("##newsc", "new scenario name", newScenario, ImGuiInputTextFlags.EnterReturnsTrue);
    ImGui.sameLine();
    if (ImGui.button("New") || enter) {
      report(editor.addScenario(newScenario.get()));
      newScenario.set("");
    }
    ImGui.sameLine();
    if (ImGui.button("Delete##scenario")) {
      report(editor.deleteActiveScenario());
    }
  }

  private static String shown(String name) {
    return name.isBlank() ? "(unnamed)" : name;
  }

  private void drawStl() {
    if (stlPicker != null) {
      ImGui.sameLine();
      if (ImGui.button("Add STL ...")) {
        stlPicker.pick().ifPresent(p -> addAndSelect(editor.addMesh(p, scale())));
      }
      return;
    }
    ImGui.setNextItemWidth(ImGui.getContentRegionAvailX() * 0.5f);
    ImGui.inputTextWithHint("##stl", "path/to/part.stl", stlPath);
    ImGui.sameLine();
    ImGui.setNextItemWidth(ImGui.getFontSize() * 3);
    ImGui.inputText("##stlscale", stlScale);
    if (ImGui.isItemHovered()) {
      Txt.tooltip("scale: mm per file unit (1000 for a file in metres)");
    }
    ImGui.sameLine();
    if (ImGui.button("Add STL")) {
      String p = stlPath.get().trim();
      if (p.isEmpty()) {
        report(new Result.Refused("STL file: type the path of a .stl file first"));
      } else {
        try {
          addAndSelect(editor.addMesh(Path.of(p), scale()));
        } catch (java.nio.file.InvalidPathException e) {
          report(new Result.Refused("STL file: not a file name ('" + e.getInput() + "': " + e.getReason() + ")"));
        }
      }
    }
  }

  private double scale() {
    try {
      return Double.parseDouble(stlScale.get().trim());
    } catch (NumberFormatException e) {
      return Double.NaN;
    }
  }

  private void drawObjectList() {
    Txt.disabledWrapped("Objects (click one here or in the 3D view)", false);
    float h = Math.min(6, Math.max(1, editor.world().objects().size())) * ImGui.getTextLineHeightWithSpacing() + 6;
    if (ImGui.beginListBox("##objects", -1, h)) {
      for (WorldObject o : editor.world().objects()) {
        String label = o.name() + "  (" + o.kind().name().toLowerCase() + o.startParent().map(p -> " on " + p).orElse("") + ")";
        if (ImGui.selectable(label + "##obj" + o.name(), o.name().equals(selected))) {
          selected = o.name();
        }
      }
      ImGui.endListBox();
    }
  }

  private void drawSelected(WorldObject o) {
    String name = o.name();
    field("name", name, name, t -> {
      Result r = editor.rename(name, t);
      if (r instanceof Result.Done && editor.world().find(t.trim()).isPresent()) {
        selected = t.trim();
      }
      return r;
    });
    ImGui.alignTextToFramePadding();
    ImGui.textUnformatted("kind");
    ImGui.sameLine();
    if (ImGui.radioButton("part", o.kind() == ObjectKind.PART) && o.kind() != ObjectKind.PART) {
      report(editor.setKind(name, ObjectKind.PART));
    }
    ImGui.sameLine();
    if (ImGui.radioButton("fixture", o.kind() == ObjectKind.FIXTURE) && o.kind() != ObjectKind.FIXTURE) {
      report(editor.setKind(name, ObjectKind.FIXTURE));
    }
    ImGui.alignTextToFramePadding();
    ImGui.textUnformatted("parent");
    ImGui.sameLine();
    ImGui.setNextItemWidth(-1);
    if (ImGui.beginCombo("##parent", o.startParent().orElse("(the cell)"))) {
      if (ImGui.selectable("(the cell)", o.startParent().isEmpty())) {
        report(editor.setParent(name, Optional.empty()));
      }
      for (WorldObject f : editor.world().objects()) {
        if (f.kind() == ObjectKind.FIXTURE && !f.name().equals(name)
            && ImGui.selectable(f.name() + "##par", o.startParent().filter(f.name()::equals).isPresent())) {
          report(editor.setParent(name, Optional.of(f.name())));
        }
      }
      ImGui.endCombo();
    }
    field("colour", name, o.colour().hex(), t -> editor.setColour(name, t));
    Txt.disabled("pose on its parent (mm, deg)");
    numbers(name, NumberField.X, NumberField.Y, NumberField.Z);
    numbers(name, NumberField.W, NumberField.P, NumberField.R);
    Txt.disabled("size");
    switch (o.shape()) {
      case Shape.Box b -> numbers(name, NumberField.LENGTH, NumberField.WIDTH, NumberField.HEIGHT);
      case Shape.Cylinder c -> numbers(name, NumberField.RADIUS, NumberField.HEIGHT);
      case Shape.Mesh m -> {
        numbers(name, NumberField.SCALE);
        Txt.disabled(m.file().getFileName().toString());
      }
    }
    if (ImGui.button("Duplicate")) {
      addAndSelect(editor.duplicate(name));
    }
    ImGui.sameLine();
    if (ImGui.button("Delete")) {
      Result r = editor.delete(name);
      report(r);
      if (r instanceof Result.Done) {
        selected = "";
      }
    }
  }

  private void numbers(String object, NumberField... fs) {
    float spacing = ImGui.getStyle().getItemSpacingX();
    float labels = 0;
    for (NumberField f : fs) {
      labels += ImGui.calcTextSize(shortLabel(f)).x + spacing;
    }
    float w = (ImGui.getContentRegionAvailX() - labels - (fs.length - 1) * spacing) / fs.length;
    for (int i = 0; i < fs.length; i++) {
      if (i > 0) {
        ImGui.sameLine();
      }
      NumberField f = fs[i];
      ImGui.alignTextToFramePadding();
      Txt.disabled(shortLabel(f));
      ImGui.sameLine();
      double v = editor.number(object, f);
      String shown = Double.isNaN(v) ? "" : String.format(java.util.Locale.ROOT, "%.3f", v).replaceAll("\\.?0+$", "")
          .replaceFirst("^-0$", "0");  // a rounding -0.0001 (or -0) reads 0
      ImGui.setNextItemWidth(w);
      textInput(f.label(), object + "/" + f.name(), shown, t -> editor.setNumber(object, f, t), f.label() + " (" + f.unit() + ")");
    }
  }

  private static String shortLabel(NumberField f) {
    return switch (f) {
      case LENGTH -> "L";
      case WIDTH -> "W";
      case HEIGHT -> "H";
      case RADIUS -> "r";
      case SCALE -> "scale";
      default -> f.label();
    };
  }

  private void field(String label, String object, String value, Function<String, Result> apply) {
    ImGui.alignTextToFramePadding();
    ImGui.textUnformatted(label);
    ImGui.sameLine(ImGui.getFontSize() * 4);
    ImGui.setNextItemWidth(-1);
    textInput(label, object + "/" + label, value, apply, label);
  }

  /**
   * A text field whose text is applied on Enter or when it loses the keyboard; Enter also gives
   * the keyboard back to the pendant (ImGui deactivates a single-line field on Enter).
   */
  private void textInput(String label, String key, String value, Function<String, Result> apply, String hint) {
    ImString buf = fields.computeIfAbsent(key, k -> new ImString(value, 64));
    boolean enter = ImGui.inputTextWithHint("##" + key, label, buf, ImGuiInputTextFlags.EnterReturnsTrue | ImGuiInputTextFlags.AutoSelectAll);
    if (ImGui.isItemHovered()) {
      Txt.tooltip(hint);
    }
    if (!ImGui.isItemActive() && !enter && !buf.get().equals(value) && !ImGui.isItemDeactivatedAfterEdit()) {
      buf.set(value);  // the model changed (undo, another field): show it
    }
    if (enter || ImGui.isItemDeactivatedAfterEdit()) {
      if (!buf.get().equals(value)) {
        report(apply.apply(buf.get()));
      }
    }
  }

  private void remember(String button) {
    buttons.put(button, new float[] {ImGui.getItemRectMinX(), ImGui.getItemRectMinY(), ImGui.getItemRectSizeX(), ImGui.getItemRectSizeY()});
  }

  /** Where a button ("Add box", "Save") was drawn last frame: x, y, w, h in display pixels (tests). */
  public Optional<float[]> buttonRect(String button) {
    return Optional.ofNullable(buttons.get(button));
  }

  /** Saves the active scenario as a scenario file (until the workspace saves the cell with it). */
  private void drawSave() {
    if (inWorkspace) {
      Txt.disabled("Edits are saved with the workspace.");
    }
    String button = inWorkspace ? "Export" : "Save";
    ImGui.setNextItemWidth(ImGui.getContentRegionAvailX() * 0.65f);
    ImGui.inputTextWithHint("##save", inWorkspace ? "export a copy as FILE.rrcell" : "save as FILE.rrcell", savePath);
    ImGui.sameLine();
    if (ImGui.button(button)) {
      try {
        report(save(Path.of(savePath.get().trim())));
      } catch (java.nio.file.InvalidPathException e) {
        report(new Result.Refused((inWorkspace ? "export as" : "save as") + ": not a file name ('" + e.getInput()
            + "': " + e.getReason() + ")"));
      }
    }
    remember(button);
  }

  /** Writes the active scenario to {@code file} (scenario format 1, through AtomicFiles). */
  public Result save(Path file) {
    String f = file.getFileName() == null ? "" : file.getFileName().toString();
    String lower = f.toLowerCase(java.util.Locale.ROOT);
    // .rrcell opens in RobotRun from a file manager; .json is the same scenario for text tools.
    if (!lower.endsWith(".rrcell") && !lower.endsWith(".json")) {
      return new Result.Refused("save as: expected a file name ending in .rrcell or .json, got '" + f + "'");
    }
    try {
      ScenarioWriter.write(editor.active(), file.toAbsolutePath());
      return new Result.Done("saved " + file);
    } catch (IOException e) {
      return new Result.Refused("save as " + file + ": " + e.getMessage());
    }
  }
}
