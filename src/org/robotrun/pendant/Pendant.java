package org.robotrun.pendant;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import java.util.function.IntConsumer;
import java.util.function.UnaryOperator;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.CoordSystem;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.control.RobotControl.ExecutionStatus;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.StartFrom;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Program;

/**
 * The teach pendant as a state machine: keys in, commands on a {@link RobotControl} out, and the
 * LCD as text ({@link #lcd()}). No drawing and no toolkit: the desktop UI draws {@link Lcd} rows
 * and forwards keys; scripts and tests do the same with {@code .keys} files.
 *
 * <p>Three controls, as on an iPendant: TP ENABLE (on/off, {@link #setTpEnabled}), DEADMAN
 * ({@link Key#DEADMAN}, held) and SHIFT (held; never latched). The pendant sends them to the
 * controller as switch signals and the controller decides: jogging and SHIFT+FWD/BWD need all
 * three; letting the DEADMAN go with the pendant enabled is SRVO-003 and stops the arm; in T1 and
 * T2 a program runs only while SHIFT and DEADMAN are held (hold-to-run). In AUTO the pendant cannot
 * jog; programs start from the operator panel's CYCLE START ({@link #cycleStart}) with the pendant
 * disabled. Every error the operator can cause ends as a message on the prompt line; no key throws.
 * Time is not the pendant's: the cell's stepper advances the controller, and {@link #follow} lets
 * the pendant catch up with what happened.
 */
public final class Pendant {
  /** Undo depth of the program editor (the issue asks for at least 50). */
  static final int UNDO_DEPTH = 100;

  private final RobotControl control;
  private final LineParser lineParser;

  final SelectScreen selectScreen = new SelectScreen();
  final EditScreen editScreen = new EditScreen();
  final DataScreen dataScreen = new DataScreen();
  final IoScreen ioScreen = new IoScreen();
  final PosnScreen posnScreen = new PosnScreen();
  final FrameScreen frameScreen = new FrameScreen();
  final JogFrameScreen jogFrameScreen = new JogFrameScreen();
  final AlarmScreen alarmScreen = new AlarmScreen();
  final UserScreen userScreen = new UserScreen();
  final TaskScreen taskScreen = new TaskScreen();
  final BgLogicScreen bgLogicScreen = new BgLogicScreen();

  private Screen screen = selectScreen;
  private final Deque<Screen> history = new ArrayDeque<>();
  private Modal modal;
  private String message = "";

  /** {@link OverrideSteps#VFINE} or {@link OverrideSteps#FINE} while the override is on one of them, else 0. */
  private int incremental;

  /** The program the EDIT screen and SHIFT+FWD work on ("" before one is chosen). */
  String selectedProgram = "";
  final Map<String, Deque<Program>> undo = new HashMap<>();
  /** Lines commented out on this pendant, by program and text, so uncomment restores them exactly. */
  final Map<String, Instruction> commentMemo = new HashMap<>();
  List<Instruction> clipboard = List.of();
  DefaultMotion defaultMotion = DefaultMotion.STANDARD.get(0);

  /** A pendant on {@code control}; uncommenting lines not commented here needs a parser (may be {@link LineParser#NONE}). */
  public Pendant(RobotControl control, LineParser lineParser) {
    this.control = Objects.requireNonNull(control, "control");
    this.lineParser = Objects.requireNonNull(lineParser, "lineParser");
  }

  /** A pendant without a TP line parser. */
  public Pendant(RobotControl control) {
    this(control, LineParser.NONE);
  }

  /** The controller this pendant drives. */
  public RobotControl control() {
    return control;
  }

  LineParser lineParser() {
    return lineParser;
  }

  // ---- input -----------------------------------------------------------------------------

  /** A key goes down. */
  public void press(Key k) {
    if (k == Key.SHIFT) {
      control.setShift(true);
      return;
    }
    if (k == Key.DEADMAN) {
      control.setDeadman(true);
      return;
    }
    if (k.isJog()) {
      jogPress(k);
      return;
    }
    message = "";
    handle(k);
    followExecution();
  }

  /**
   * A key comes up: a held jog key stops. SHIFT up stops jogging and, in T1/T2, pauses a running
   * program (hold-to-run); DEADMAN up with the pendant enabled is SRVO-003.
   */
  public void release(Key k) {
    if (k == Key.SHIFT) {
      say(control.setShift(false));
      return;
    }
    if (k == Key.DEADMAN) {
      say(control.setDeadman(false));
      return;
    }
    if (k.isJog()) {
      control.jogKeyUp(k.jogAxis(), k.jogSign());
    }
  }

  /** Shows what the controller said about a switch ("" leaves the prompt line as it is). */
  private void say(Result r) {
    String text = switch (r) {
      case Result.Ok ok -> ok.message();
      case Result.Refused no -> no.reason();
    };
    if (!text.isEmpty()) {
      message = text;
    }
  }

  // ---- the pendant's switches and the operator panel ------------------------------------------

  /** TP ENABLE switched on or off. Turning it off stops jogging. */
  public void setTpEnabled(boolean on) {
    control.setTpEnabled(on);
    message = on ? "TP enabled" : "TP disabled";
  }

  /** Whether the TP ENABLE switch is on. */
  public boolean tpEnabled() {
    return control.tpEnabled();
  }

  /** Whether the DEADMAN is held. */
  public boolean deadmanHeld() {
    return control.deadmanHeld();
  }

  /** The operator panel's mode switch turns: a running program pauses, jogging stops. */
  public void setMode(RobotControl.Mode mode) {
    ExecutionStatus before = control.status();
    control.setMode(mode);
    // a run the mode switch stopped says so (the controller holds it; see ControllerPort.setMode)
    message = before.state() == ExecState.RUNNING && control.status().state() != ExecState.RUNNING
        ? "Mode " + mode + ": " + before.program() + " paused at line " + control.status().line() + " by the mode switch"
        : "Mode " + mode;
  }

  /** An E-stop button is pressed: the pendant's (SRVO-002) or the operator panel's (SRVO-001). */
  public void emergencyStop(boolean fromPendant) {
    control.emergencyStop(fromPendant);
    message = (fromPendant ? "Teach pendant E-stop" : "Operator panel E-stop") + ": release it, then RESET";
  }

  /** The E-stop buttons are twisted out (the alarm stays until RESET). */
  public void releaseEmergencyStop() {
    control.releaseEmergencyStop();
    message = "E-stop released: press RESET";
  }

  /**
   * The operator panel's CYCLE START: in AUTO, with the pendant disabled, runs the selected
   * program from its cursor line (a paused one resumes).
   */
  public void cycleStart() {
    if (control.mayStart(StartFrom.OPERATOR_PANEL, true) instanceof Result.Refused no) {
      message = no.reason();
      return;
    }
    startProgram(StartFrom.OPERATOR_PANEL, true);
  }

  /**
   * A click on an on-screen jog key: latched jogging (the axis runs until clicked again, or the
   * deadman is released). Other keys: a tap.
   */
  public void click(Key k) {
    if (!k.isJog()) {
      tap(k);
      return;
    }
    jogDown(k, true);
  }

  /** Press and release. */
  public void tap(Key k) {
    press(k);
    release(k);
  }

  /** Typed text: goes to an open entry, or starts one on the field under the cursor. */
  public void type(String text) {
    if (modal instanceof Modal.Entry e) {
      e.append(text);
      return;
    }
    if (modal != null) {
      message = "Finish the open prompt first (ENTER or PREV)";
      return;
    }
    message = "";
    screen.text(this, text);
  }

  /**
   * Whether a text or number entry is open on the prompt line, so that typed characters go to
   * it (a keyboard front end then sends letters as text instead of as jog keys).
   */
  public boolean entryOpen() {
    return modal instanceof Modal.Entry;
  }

  /** Whether SHIFT is held. */
  public boolean shift() {
    return control.shiftHeld();
  }

  /** The jog coordinate system COORD selects. */
  public CoordSystem coord() {
    return control.coordSystem();
  }

  private void jogPress(Key k) {
    jogDown(k, false);
  }

  /**
   * The override level: {@link OverrideSteps#VFINE}, {@link OverrideSteps#FINE} or the
   * percentage (a program's OVERRIDE or another pendant key leaves VFINE/FINE).
   */
  int overrideLevel() {
    if (incremental != 0 && control.overridePct() != 1) {
      incremental = 0;
    }
    return incremental != 0 ? incremental : control.overridePct();
  }

  private void jogDown(Key k, boolean latched) {
    if (overrideLevel() < 0) {
      // VFINE / FINE: one increment per key press, nothing while the key stays down
      Result r = control.jogIncrement(k.jogAxis(), k.jogSign(), overrideLevel() == OverrideSteps.VFINE);
      message = switch (r) {
        case Result.Ok ok -> ok.message();
        case Result.Refused no -> no.reason();
      };
      return;
    }
    Result r = control.jogKeyDown(k.jogAxis(), k.jogSign(), latched);
    seenJogStop = "";
    message = switch (r) {
      case Result.Ok ok -> ok.message();
      case Result.Refused no -> no.reason();
    };
  }

  private void handle(Key k) {
    if (modal != null) {
      modalKey(k);
      return;
    }
    switch (k) {
      case SELECT -> show(selectScreen);
      case EDIT -> openEditor();
      case DATA -> show(dataScreen);
      case POSN -> show(posnScreen);
      case IO -> show(ioScreen);
      case STATUS -> show(alarmScreen);
      case MENU -> menu();
      case FCTN -> function();
      case DISP -> {
        Screen back = history.peek();
        if (back != null) {
          show(back);
        } else {
          message = "No other screen to display";
        }
      }
      case PREV -> {
        if (!screen.prev(this)) {
          if (history.isEmpty()) {
            message = "No previous screen";
          } else {
            screen = history.pop();
          }
        }
      }
      case COORD -> {
        if (shift()) {
          frameSelectMenu();
        } else {
          CoordSystem coord = CoordSystem.values()[(coord().ordinal() + 1) % CoordSystem.values().length];
          control.setCoordSystem(coord);
          message = "Jog coordinates: " + coord + "  (Tool " + control.activeFrame(FrameKind.TOOL) + ", Jog "
              + control.activeJogFrame() + ", User " + control.activeFrame(FrameKind.USER) + ")";
        }
      }
      case STEP -> {
        control.setStepMode(!control.stepMode());
        message = control.stepMode() ? "Single step on" : "Single step off";
      }
      case HOLD -> {
        control.hold();
        message = "HOLD";
      }
      case FWD, BWD -> run(k == Key.FWD);
      case RESET -> {
        if (control.emergencyStopped()) {
          message = "E-stop still pressed: release it first, then RESET";
          return;
        }
        boolean had = control.activeAlarm().isPresent();
        control.reset();
        message = had ? "Alarm reset" : "RESET";
      }
      case OVERRIDE_UP, OVERRIDE_DOWN -> {
        int level = OverrideSteps.next(overrideLevel(), k == Key.OVERRIDE_UP, shift());
        // VFINE and FINE jog in increments; programs run at 1 % meanwhile
        incremental = level < 0 ? level : 0;
        control.setOverridePct(Math.max(1, level));
        message = "Override " + OverrideSteps.display(level)
            + (level < 0 ? ": incremental jog, one step per jog key press" : "");
      }
      case TOOL1, TOOL2 -> toggleHand(k == Key.TOOL1 ? 1 : 2);
      default -> screen.key(this, k);
    }
  }

  private void toggleHand(int port) {
    boolean on = !control.registers().bit(IoKind.RO, port);
    control.registers().setBit(IoKind.RO, port, on);
    message = "RO[" + port + "]=" + (on ? "ON" : "OFF") + (port == 1 ? (on ? " (hand closed)" : " (hand open)") : "");
  }

  private void run(boolean forward) {
    if (control.mayStart(StartFrom.TEACH_PENDANT, forward) instanceof Result.Refused no) {
      message = no.reason();
      return;
    }
    startProgram(StartFrom.TEACH_PENDANT, forward);
  }

  private void startProgram(StartFrom from, boolean forward) {
    // the program in the editor (a callee the cursor followed into), else the selected one
    String name = !editScreen.programName.isEmpty() && control.program(editScreen.programName).isPresent()
        ? editScreen.programName : selectedProgram;
    if (name.isEmpty() || control.program(name).isEmpty()) {
      message = "No program selected: choose one on SELECT";
      return;
    }
    int line = editScreen.cursorLine(this);
    int count = control.program(name).get().lineCount();
    if (line > count) {
      if (!forward && count > 0) {
        line = count + 1;
      } else {
        message = "Cursor at [End]: move it to the line to start from";
        return;
      }
    }
    Result r = control.run(from, name, line, forward);
    boolean fromLastLine = forward && line == count && count > 1;
    // the cursor left on an END where the last run ended: the program ends at once, which a student
    // takes for CYCLE START or SHIFT+FWD doing nothing (a deliberate addition, docs/pendant.md)
    boolean onEnd = forward && line >= 1 && line <= count && control.program(name).get().line(line) instanceof Instruction.End;
    int startLine = line;
    message = switch (r) {
      case Result.Ok ok when ok.message().isEmpty() && onEnd ->
          "Started at line " + startLine + " of " + name + ", an END: it ended at once; for the whole program put the cursor on line 1";
      case Result.Ok ok when ok.message().isEmpty() && fromLastLine ->
          // the cursor stayed on the last line after a run: only that line runs, which a student
          // takes for nothing happening; say so (a deliberate addition, docs/pendant.md)
          "Started at line " + startLine + ", the last line of " + name + ": for the whole program put the cursor on line 1";
      case Result.Ok ok -> ok.message();
      case Result.Refused no -> no.reason();
    };
  }

  /**
   * Catches up with the controller after simulated time passed (the cell's stepper advanced it):
   * a MESSAGE[] a program wrote, why a jog stopped by itself, and the EDIT cursor following the
   * executing line.
   */
  public void follow() {
    followExecution();
  }

  private void followExecution() {
    int messages = control.userMessages().size();
    if (messages > seenMessages && messages > 0) {
      // a program wrote MESSAGE[]: show it on the prompt line (the USER screen keeps them all)
      message = "MESSAGE: " + control.userMessages().get(messages - 1);
    }
    seenMessages = messages;
    String jogStop = control.jogStopReason();
    if (!jogStop.isEmpty() && !jogStop.equals(seenJogStop)) {
      // the jog stopped itself (limit, reach, singularity): say why, with the axis and value
      message = "Jog stopped: " + jogStop;
    }
    seenJogStop = jogStop;
    ExecutionStatus st = control.status();
    // follow only when execution moved (so a paused program's cursor can be moved by the operator),
    // and once more when it stops (so the cursor ends where it ended)
    if (st.equals(lastFollowed)) {
      return;
    }
    boolean justStopped = st.state() == ExecState.IDLE && lastFollowed != null && lastFollowed.state() != ExecState.IDLE;
    boolean active = st.state() == ExecState.RUNNING || st.state() == ExecState.PAUSED;
    if (active && !editScreen.programName.isEmpty() && !st.program().equals(editScreen.programName)
        && control.program(st.program()).isPresent()) {
      // into a CALLed program and back out: the editor shows the program that executes
      editScreen.open(this, st.program());
    }
    if ((st.state() != ExecState.IDLE || justStopped) && st.program().equals(editScreen.programName) && st.line() > 0) {
      editScreen.follow(this, st.line());
    }
    lastFollowed = st;
  }

  private ExecutionStatus lastFollowed;
  private int seenMessages;
  /** The controller's last jog-stop reason already shown on the prompt line. */
  private String seenJogStop = "";

  private void menu() {
    List<String> items = List.of("SELECT", "EDIT", "DATA", "I/O", "SETUP Frames", "POSITION", "STATUS Alarm", "USER",
        "SETUP BG Logic", "STATUS Program");
    choose("MENU", items, i -> {
      switch (i) {
        case 0 -> show(selectScreen);
        case 1 -> openEditor();
        case 2 -> show(dataScreen);
        case 3 -> show(ioScreen);
        case 4 -> show(frameScreen);
        case 5 -> show(posnScreen);
        case 6 -> show(alarmScreen);
        case 7 -> show(userScreen);
        case 8 -> show(bgLogicScreen);
        default -> show(taskScreen);
      }
    });
  }

  private void function() {
    choose("FUNCTION", List.of("ABORT (ALL)", "Set active UTOOL/UFRAME"), i -> {
      switch (i) {
        case 0 -> {
          control.abort();
          message = "Program aborted";
        }
        default -> frameSelectMenu();
      }
    });
  }

  /** SETUP Frames [TYPE]: tool, user or jog frames. */
  void frameTypeMenu() {
    choose("Frame type", List.of("Tool Frame", "User Frame", "Jog Frame"), i -> {
      if (i == 2) {
        screen = jogFrameScreen;
      } else {
        frameScreen.showKind(i == 0 ? FrameKind.TOOL : FrameKind.USER);
        screen = frameScreen;
      }
    });
  }

  /** SHIFT+COORD: choose the active tool or user frame. */
  void frameSelectMenu() {
    choose("Active frame", List.of("Tool frame (UTOOL)", "User frame (UFRAME)"), which -> {
      FrameKind kind = which == 0 ? FrameKind.TOOL : FrameKind.USER;
      String word = kind == FrameKind.TOOL ? "UTOOL" : "UFRAME";
      entry("Active " + word + " (0-10):", Integer.toString(control.activeFrame(kind)), false, t -> {
        Optional<Integer> n = parseInt(t, 0, 10);
        if (n.isEmpty()) {
          return Optional.of(word + ": enter 0 to 10, got '" + t.trim() + "'");
        }
        control.selectFrame(kind, n.get());
        message = word + "_NUM=" + n.get();
        return Optional.empty();
      });
    });
  }

  void openEditor() {
    if (selectedProgram.isEmpty() || control.program(selectedProgram).isEmpty()) {
      show(selectScreen);
      message = "No program selected: choose one and press ENTER";
      return;
    }
    editScreen.open(this, selectedProgram);
    show(editScreen);
  }

  /** Switches screens (PREV comes back). */
  void show(Screen s) {
    if (s != screen) {
      history.push(screen);
      while (history.size() > 20) {
        history.removeLast();
      }
      screen = s;
    }
  }

  /** Back to the screen shown before this one. */
  void prevScreen() {
    if (!history.isEmpty()) {
      screen = history.pop();
    }
  }

  /** The screen on display. */
  public Screen screen() {
    return screen;
  }

  // ---- modal prompts -----------------------------------------------------------------------

  void choose(String title, List<String> options, IntConsumer onChoose) {
    modal = new Modal.Choice(title, options, onChoose);
  }

  /** A choice list opening on item {@code current} (the field's value now), as a controller's does. */
  void choose(String title, List<String> options, int current, IntConsumer onChoose) {
    Modal.Choice c = new Modal.Choice(title, options, onChoose);
    c.cursor = Math.max(0, Math.min(current, options.size() - 1));
    modal = c;
  }

  /**
   * The item of {@code options} a field showing {@code text} holds: the same text, else the
   * longest item the text starts with ({@code CNT50} is {@code CNT}), else 0.
   */
  static int currentChoice(List<String> options, String text) {
    String t = text.strip().toUpperCase(Locale.ROOT);
    // an item field DO[3] matches the item DO[...]
    String kind = t.indexOf('[') > 0 ? t.substring(0, t.indexOf('[')) : t;
    int best = -1;
    int bestLength = 0;
    for (int i = 0; i < options.size(); i++) {
      String o = options.get(i).strip().toUpperCase(Locale.ROOT).replace("[...]", "");
      if (o.equals(t) || o.equals(kind)) {
        return i;
      }
      if (!o.isEmpty() && t.startsWith(o) && o.length() > bestLength) {
        best = i;
        bestLength = o.length();
      }
    }
    return Math.max(best, 0);
  }

  /** An entry offering {@code initial}: the first typed character replaces it, ENTER keeps it. */
  void entry(String prompt, String initial, boolean letters, Function<String, Optional<String>> onEnter) {
    modal = new Modal.Entry(prompt, initial, true, letters, onEnter);
  }

  /** {@link #entryTyped} when the operator already typed something ({@code typed} non-null), else {@link #entry}. */
  void entryOrTyped(String prompt, String typed, String offered, boolean letters,
      Function<String, Optional<String>> onEnter) {
    if (typed != null) {
      entryTyped(prompt, typed, letters, onEnter);
    } else {
      entry(prompt, offered, letters, onEnter);
    }
  }

  /** An entry that starts with text already typed (a keypad digit that opened it). */
  void entryTyped(String prompt, String typed, boolean letters, Function<String, Optional<String>> onEnter) {
    modal = new Modal.Entry(prompt, typed, false, letters, onEnter);
  }

  void confirm(String question, Runnable onYes) {
    modal = new Modal.Confirm(question, onYes);
  }

  private void modalKey(Key k) {
    switch (modal) {
      case Modal.Choice c -> {
        switch (k) {
          case UP -> c.cursor = Math.max(0, c.cursor - 1);
          case DOWN -> c.cursor = Math.min(c.options.size() - 1, c.cursor + 1);
          case ENTER -> pick(c, c.cursor);
          case PREV -> modal = null;
          default -> {
            int d = k.digit();
            if (d >= 1 && d <= c.options.size()) {
              pick(c, d - 1);
            } else if (d == 0 && c.options.size() >= 10) {
              pick(c, 9);
            } else {
              message = "Choose with UP/DOWN and ENTER (or 1-" + Math.min(9, c.options.size()) + "); PREV cancels";
            }
          }
        }
      }
      case Modal.Entry e -> {
        if (k.keypadChar().isPresent()) {
          e.append(String.valueOf(k.keypadChar().get()));
          return;
        }
        switch (k) {
          case BACKSPACE -> {
            e.settle();
            e.fresh = false;
            if (e.buffer.length() > 0) {
              e.buffer.setLength(e.buffer.length() - 1);
            }
          }
          case F1, F2, F3, F4, F5 -> {
            if (e.letters) {
              e.letterKey(k.ordinal() - Key.F1.ordinal());
            }
          }
          case RIGHT -> e.settle();
          case ENTER -> {
            modal = null;
            Optional<String> err = e.onEnter.apply(e.buffer.toString());
            err.ifPresent(m -> message = m);
          }
          case PREV -> {
            modal = null;
            message = "Entry cancelled";
          }
          default -> message = "Entry open: ENTER accepts, PREV cancels";
        }
      }
      case Modal.Confirm c -> {
        switch (k) {
          case F4 -> {
            modal = null;
            c.onYes.run();
          }
          case F5, PREV -> {
            modal = null;
            message = "Cancelled";
          }
          default -> message = c.question + " F4 YES / F5 NO";
        }
      }
    }
  }

  private void pick(Modal.Choice c, int i) {
    modal = null;
    c.onChoose.accept(i);
  }

  // ---- helpers for screens ----------------------------------------------------------------

  /** Shows {@code text} on the prompt line. */
  void message(String text) {
    message = text;
  }

  /** The prompt line's current message. */
  public String message() {
    return message;
  }

  /** Why programs cannot be changed here ("" when they can): shown on the prompt line at each refused edit. */
  private String readOnly = "";

  /**
   * Makes every program read-only, as a write-protected program is on a controller: creating,
   * deleting, copying, renaming, a comment, a line edit, TOUCHUP and UNDO are refused with
   * {@code why} on the prompt line, and nothing changes (a hand-in opened to look at, issue 26).
   * Running, jogging and the data screens still work; they change nothing of the hand-in.
   */
  public void setReadOnly(String why) {
    readOnly = why == null ? "" : why;
  }

  /** Why programs cannot be changed here, "" when they can. */
  public String readOnlyReason() {
    return readOnly;
  }

  /**
   * Changes program {@code name} through {@code edit}, keeping the old version for undo. A
   * running program is not edited (message instead). Returns whether it changed.
   */
  boolean editProgram(String name, UnaryOperator<Program> edit) {
    if (!readOnly.isEmpty()) {
      message = readOnly;
      return false;
    }
    ExecutionStatus st = control.status();
    if (st.state() == ExecState.RUNNING && st.program().equals(name)) {
      message = "Program is running: HOLD or abort it before editing";
      return false;
    }
    Optional<Program> before = control.program(name);
    if (before.isEmpty()) {
      message = "Program " + name + " no longer exists";
      return false;
    }
    Program after = edit.apply(before.get());
    if (after == null || after.equals(before.get())) {
      return false;
    }
    Optional<String> dup = newDuplicateLabel(before.get(), after);
    if (dup.isPresent()) {
      message = dup.get();
      return false;
    }
    Optional<String> refused = lineParser.refusal(before.get(), after);
    if (refused.isPresent()) {
      message = refused.get();
      return false;
    }
    Deque<Program> stack = undo.computeIfAbsent(name, n -> new ArrayDeque<>());
    stack.push(before.get());
    while (stack.size() > UNDO_DEPTH) {
      stack.removeLast();
    }
    saveKeepingCursor(after);
    warnNoEffect(before.get(), after);
    return true;
  }

  private void warnNoEffect(Program before, Program after) {
    noEffectAdded(before, after).ifPresent(w -> message = "Warning: " + w);
  }

  /** The warning for a line {@code after} adds that the simulator runs without effect (PAYLOAD, Wjnt). */
  static Optional<String> noEffectAdded(Program before, Program after) {
    java.util.Set<Instruction> had = new java.util.HashSet<>(before.lines());
    for (Instruction in : after.lines()) {
      if (!had.contains(in)) {
        Optional<String> w = org.robotrun.program.SimulatorEffects.noEffect(in);
        if (w.isPresent()) {
          return w;
        }
      }
    }
    return Optional.empty();
  }

  /**
   * Saves an edit. A paused program goes on in the edited code, so its line may shift (lines
   * inserted above it); that is not execution moving, so the operator's cursor stays put.
   */
  private void saveKeepingCursor(Program edited) {
    ExecutionStatus before = control.status();
    control.saveProgram(edited);
    if (before.equals(lastFollowed)) {
      lastFollowed = control.status();
    }
  }

  /** A label number defined twice in {@code after} but not in {@code before}, as a message. */
  static Optional<String> newDuplicateLabel(Program before, Program after) {
    Map<Integer, Integer> seenBefore = labels(before);
    Map<Integer, Integer> first = new HashMap<>();
    for (int n = 1; n <= after.lineCount(); n++) {
      if (after.line(n) instanceof Instruction.Label l) {
        Integer at = first.putIfAbsent(l.number(), n);
        if (at != null && seenBefore.getOrDefault(l.number(), 0) < 2) {
          return Optional.of("Duplicate label: LBL[" + l.number() + "] is already on line " + at);
        }
      }
    }
    return Optional.empty();
  }

  private static Map<Integer, Integer> labels(Program p) {
    Map<Integer, Integer> count = new HashMap<>();
    for (Instruction in : p.lines()) {
      if (in instanceof Instruction.Label l) {
        count.merge(l.number(), 1, Integer::sum);
      }
    }
    return count;
  }

  /** Undoes the last edit of program {@code name}. */
  void undo(String name) {
    Deque<Program> stack = undo.get(name);
    if (stack == null || stack.isEmpty()) {
      message = "Nothing to undo";
      return;
    }
    saveKeepingCursor(stack.pop());
    message = "Undone (" + stack.size() + " more)";
  }

  static Optional<Integer> parseInt(String text, int lo, int hi) {
    try {
      int v = Integer.parseInt(text.trim());
      return v < lo || v > hi ? Optional.empty() : Optional.of(v);
    } catch (NumberFormatException e) {
      return Optional.empty();
    }
  }

  // ---- LCD ---------------------------------------------------------------------------------

  /** The LCD as it stands. */
  public Lcd lcd() {
    followExecution();
    List<String> body;
    String prompt = message;
    List<String> keys;
    String title = screen.title(this, Lcd.WIDTH);
    switch (modal) {
      case null -> {
        body = screen.body(this);
        keys = screen.functionKeys(this);
      }
      case Modal.Choice c -> {
        body = choiceBody(c);
        keys = List.of("", "", "", "", "");
        // the list's name stays whole at the row's end; the screen's title gives way
        String tail = " - " + c.title;
        title = screen.title(this, Lcd.WIDTH - tail.length()) + tail;
        if (prompt.isEmpty()) {
          prompt = "Select item (UP/DOWN, ENTER or number; PREV cancels)";
        }
      }
      case Modal.Entry e -> {
        body = screen.body(this);
        prompt = e.prompt + " " + e.buffer + "_";
        keys = e.letters ? Modal.Entry.LETTER_GROUPS : List.of("", "", "", "", "");
      }
      case Modal.Confirm c -> {
        body = screen.body(this);
        prompt = c.question;
        keys = List.of("", "", "", "YES", "NO");
      }
    }
    return Lcd.of(statusLine(), control.activeAlarm().or(control::lastWarning).map(RobotControl.AlarmEntry::display).orElse(""), title, body,
        prompt, keys);
  }

  /** The LCD as text (what {@code SHOW} prints). */
  public String render() {
    return lcd().toString();
  }

  /**
   * The status line as an iPendant shows it: program, line, mode (T1/T2/AUTO), execution state
   * (a program that is neither running nor paused reads ABORTED, as after END on a controller),
   * jog coordinates and override; then the lamps STEP, and SHIFT/DEADMAN/TP OFF. The active
   * frame numbers are on the POSITION screen and in the COORD message, where a controller shows
   * them.
   */
  private String statusLine() {
    String line0 = statusFields();
    // In a cell of several robots the status line starts with the robot this pendant drives.
    return robotLabel.isEmpty() ? line0 : robotLabel + " " + line0;
  }

  private String robotLabel = "";

  /**
   * Names the robot this pendant drives at the start of the status line (a cell of several
   * robots, as a multi-group pendant shows its group); empty (the default) shows none.
   */
  public void setRobotLabel(String label) {
    robotLabel = java.util.Objects.requireNonNull(label, "label");
  }

  /** The robot named on the status line; empty when none is. */
  public String robotLabel() {
    return robotLabel;
  }

  private String statusFields() {
    ExecutionStatus st = control.status();
    String prog = st.program().isEmpty() ? selectedProgram : st.program();
    int line = st.program().isEmpty() || st.state() == ExecState.IDLE && !st.program().equals(selectedProgram)
        ? (selectedProgram.isEmpty() ? 0 : editScreen.cursorLine(this)) : st.line();
    String state = switch (st.state()) {
      case IDLE, ABORTED -> "ABORTED";
      case RUNNING -> "RUNNING";
      case PAUSED -> "PAUSED";
    };
    // lamps, most urgent first (the row is 64 characters: the last ones may be cut)
    StringBuilder lamps = new StringBuilder();
    if (control.emergencyStopped()) {
      lamps.append(" E-STOP");
    }
    if (control.stepMode()) {
      lamps.append(" STEP");
    }
    if (!tpEnabled()) {
      lamps.append(" TP-OFF");
    }
    if (shift()) {
      lamps.append(" SHIFT");
    }
    if (deadmanHeld()) {
      lamps.append(" DEADMAN");
    }
    return String.format(Locale.ROOT, "%-12s LINE %-4d %-4s %-7s %-5s %4s%s",
        prog.isEmpty() ? "(none)" : prog.length() > 12 ? prog.substring(0, 12) : prog, line,
        control.mode(), state, coord(), OverrideSteps.display(overrideLevel()), lamps);
  }

  private static List<String> choiceBody(Modal.Choice c) {
    List<String> rows = new ArrayList<>();
    int top = Math.max(0, Math.min(c.cursor - Lcd.BODY_ROWS / 2, c.options.size() - Lcd.BODY_ROWS));
    for (int i = top; i < c.options.size() && rows.size() < Lcd.BODY_ROWS; i++) {
      rows.add((i == c.cursor ? ">" : " ") + String.format(Locale.ROOT, "%2d ", i + 1) + c.options.get(i));
    }
    return rows;
  }
}
