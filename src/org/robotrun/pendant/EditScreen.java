package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robotrun.pendant.ExprText.BadText;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * EDIT: numbered lines of the selected program with the cursor on a line number or a field.
 * Fields are edited by typed or keypad entry and by choice lists; POINT (SHIFT+F1) records a
 * motion line, TOUCHUP (SHIFT+F5) re-records the position under the cursor, [INST] inserts any
 * statement, [EDCMD] edits lines (insert, delete, copy/cut/paste, find, replace, renumber,
 * comment, undo). NEXT shows the second row of function keys.
 */
final class EditScreen implements Screen {
  String programName = "";
  private int line = 1;
  /** Index into the line's fields, -1 on the line number. */
  private int field = -1;
  private int page;
  private int top;
  /** Start line of a selection (copy/cut/delete), 0 when none. */
  private int selectionStart;
  private String findText = "";

  void open(Pendant p, String name) {
    if (!name.equals(programName)) {
      programName = name;
      line = 1;
      field = -1;
      top = 0;
      selectionStart = 0;
    }
  }

  private Program program(Pendant p) {
    return p.control().program(programName).orElse(Program.of(programName, List.of()));
  }

  int cursorLine(Pendant p) {
    int n = program(p).lineCount();
    line = Math.max(1, Math.min(line, n + 1));
    return line;
  }

  /** Moves the cursor to the executing line. */
  void follow(Pendant p, int executing) {
    if (executing != line) {
      line = executing;
      field = -1;
    }
  }

  private List<Field> fields(Pendant p, Program prog, int n) {
    if (n < 1 || n > prog.lineCount()) {
      return List.of();
    }
    return TpLine.fields(prog.line(n), prog, p.control().programNames(), p.control().maxLinearSpeedMmPerSec());
  }

  // ---- display -----------------------------------------------------------------------------

  @Override
  public String title(Pendant p) {
    return title(p, Lcd.WIDTH);
  }

  /**
   * "EDIT NAME  comment   LINE n/m": when the row has no room for it all, the comment is
   * shortened (ending in "..") or left out, never the line number (an .LS file's comment may be
   * longer than a controller's 16 characters).
   */
  @Override
  public String title(Pendant p, int room) {
    Program prog = program(p);
    String head = "EDIT " + programName;
    String tail = String.format(Locale.ROOT, "   LINE %d/%d", cursorLine(p), prog.lineCount());
    String comment = prog.comment().isEmpty() ? "" : "  " + prog.comment();
    int left = room - head.length() - tail.length();
    if (comment.length() > left) {
      comment = left >= 5 ? comment.substring(0, left - 2).stripTrailing() + ".." : "";
    }
    String t = head + comment + tail;
    return t.length() <= room ? t : t.substring(0, Math.max(0, room));
  }

  @Override
  public List<String> body(Pendant p) {
    Program prog = program(p);
    int cur = cursorLine(p);
    // every program line as one or more display rows (long lines wrap)
    List<String> rows = new ArrayList<>();
    int cursorRow = 0;
    for (int n = 1; n <= prog.lineCount() + 1; n++) {
      boolean isCursor = n == cur;
      boolean selected = selectionStart > 0 && n >= Math.min(selectionStart, cur) && n <= Math.max(selectionStart, cur)
          && n <= prog.lineCount();
      String marker = isCursor ? ">" : selected ? "*" : " ";
      if (isCursor) {
        cursorRow = rows.size();
      }
      if (n > prog.lineCount()) {
        rows.add(marker + "[End]");
        break;
      }
      String number = String.format(Locale.ROOT, "%4d:", n);
      if (isCursor && field < 0) {
        number = String.format(Locale.ROOT, "%5s", "{" + n + ":}");
      }
      StringBuilder text = new StringBuilder();
      List<Field> fs = fields(p, prog, n);
      for (int i = 0; i < fs.size(); i++) {
        String t = fs.get(i).text();
        text.append(isCursor && i == field ? "{" + t + "}" : t);
      }
      String full = marker + number + "  " + text;
      int width = Lcd.WIDTH;
      rows.add(full.length() <= width ? full : full.substring(0, width));
      for (int at = width; at < full.length(); at += width - 9) {
        rows.add(" ".repeat(9) + full.substring(at, Math.min(full.length(), at + width - 9)));
      }
    }
    if (cursorRow < top) {
      top = cursorRow;
    } else if (cursorRow >= top + Lcd.BODY_ROWS) {
      top = cursorRow - Lcd.BODY_ROWS + 1;
    }
    top = Math.max(0, Math.min(top, Math.max(0, rows.size() - 1)));
    return rows.subList(top, Math.min(rows.size(), top + Lcd.BODY_ROWS));
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    if (selectionStart > 0) {
      return List.of("", "COPY", "CUT", "DELETE", "CANCEL");
    }
    return page == 0 ? List.of("POINT", "[INST]", "[EDCMD]", "[CHOICE]", "TOUCHUP >")
        : List.of("POSITION", "FIND", "REPLACE", "UNDO", "COMMENT >");
  }

  // ---- keys --------------------------------------------------------------------------------

  @Override
  public void key(Pendant p, Key k) {
    Program prog = program(p);
    int cur = cursorLine(p);
    if (selectionStart > 0 && selectionKey(p, k, prog, cur)) {
      return;
    }
    List<Field> fs = fields(p, prog, cur);
    if (field >= fs.size() || field >= 0 && !fs.get(field).editable()) {
      // the line changed under the cursor (undo, paste, another screen): back to its number
      field = -1;
    }
    switch (k) {
      case UP -> move(p, p.shift() ? -Lcd.BODY_ROWS : -1);
      case DOWN -> move(p, p.shift() ? Lcd.BODY_ROWS : 1);
      case RIGHT -> {
        for (int i = field + 1; i < fs.size(); i++) {
          if (fs.get(i).editable()) {
            field = i;
            return;
          }
        }
      }
      case LEFT -> {
        int to = -1;
        for (int i = field - 1; i >= 0; i--) {
          if (fs.get(i).editable()) {
            to = i;
            break;
          }
        }
        field = to;
      }
      case NEXT -> page = 1 - page;
      case ENTER -> editField(p, prog, cur, fs, null);
      case ITEM -> p.entry("Line number:", "", false, t -> {
        Optional<Integer> n = Pendant.parseInt(t, 1, prog.lineCount() + 1);
        if (n.isEmpty()) {
          return Optional.of("Line must be 1.." + (prog.lineCount() + 1) + ", got '" + t.trim() + "'");
        }
        line = n.get();
        field = -1;
        return Optional.empty();
      });
      case F1 -> {
        if (page == 1) {
          positionDetail(p, prog, cur);
        } else if (p.shift()) {
          point(p, p.defaultMotion);
        } else {
          defaultMenu(p);
        }
      }
      case F2 -> {
        if (page == 1) {
          find(p);
        } else {
          instMenu(p);
        }
      }
      case F3 -> {
        if (page == 1) {
          replace(p);
        } else {
          edcmd(p);
        }
      }
      case F4 -> {
        if (page == 1) {
          p.undo(programName);
        } else if (field < 0 && cur <= prog.lineCount() && prog.line(cur) instanceof Instruction.Move m) {
          p.choose("Motion option", InstMenu.MOTION_OPTIONS, i -> {
            if (p.editProgram(programName, pr -> ProgramEdits.replaceLine(pr, cur, TpLine.withOption(m, m.options().size(),
                InstMenu.motionOption(i))))) {
              p.message("Option added");
            }
          });
        } else if (field >= 0 && field < fs.size()
            && fs.get(field).edit().map(e -> !e.choices().isEmpty()).orElse(false)) {
          editField(p, prog, cur, fs, null);
        } else {
          p.message("[CHOICE]: put the cursor on a field with choices (or a motion line number for options)");
        }
      }
      case F5 -> {
        if (page == 1) {
          toggleComment(p, prog, cur);
        } else if (p.shift()) {
          touchup(p, prog, cur);
        } else {
          p.message("TOUCHUP: hold SHIFT and press F5");
        }
      }
      default -> {
        Optional<Character> c = k.keypadChar();
        if (c.isPresent()) {
          editField(p, prog, cur, fs, String.valueOf(c.get()));
        } else {
          p.message("EDIT: arrows move, ENTER edits a field, F-keys as labelled");
        }
      }
    }
  }

  @Override
  public void text(Pendant p, String s) {
    Program prog = program(p);
    int cur = cursorLine(p);
    editField(p, prog, cur, fields(p, prog, cur), s);
  }

  @Override
  public boolean prev(Pendant p) {
    if (selectionStart > 0) {
      selectionStart = 0;
      p.message("Selection cancelled");
      return true;
    }
    return false;
  }

  private void move(Pendant p, int by) {
    int n = program(p).lineCount();
    line = Math.max(1, Math.min(n + 1, line + by));
    field = -1;
  }

  /** ENTER, [CHOICE] or typing on the field under the cursor. */
  private void editField(Pendant p, Program prog, int cur, List<Field> fs, String typed) {
    if (field < 0 || field >= fs.size()) {
      p.message(cur > prog.lineCount() ? "[End]: insert with POINT or [INST]" : "Move RIGHT onto a field to edit it");
      return;
    }
    Optional<Field.Edit> maybe = fs.get(field).edit();
    if (maybe.isEmpty()) {
      p.message("This text is fixed: move RIGHT onto a field");
      return;
    }
    Field.Edit edit = maybe.get();
    int keep = field;
    if (typed == null && !edit.choices().isEmpty()) {
      p.choose(fs.get(field).text(), edit.choices(), Pendant.currentChoice(edit.choices(), fs.get(field).text()), i -> {
        if (p.editProgram(programName, pr -> ProgramEdits.replaceLine(pr, cur, edit.choose().apply(i)))) {
          field = Math.min(keep, fields(p, program(p), cur).size() - 1);
          adjustPositions(p, cur);
        }
      });
      return;
    }
    if (edit.entry().isEmpty()) {
      p.message("Choose with ENTER or [CHOICE]");
      return;
    }
    p.entryOrTyped("Enter value:", typed, edit.initial(), false, t -> {
      try {
        Instruction changed = edit.entry().get().apply(t);
        if (p.editProgram(programName, pr -> ProgramEdits.replaceLine(pr, cur, changed))) {
          field = Math.min(keep, fields(p, program(p), cur).size() - 1);
        }
        return Optional.empty();
      } catch (BadText e) {
        return Optional.of(e.promptText());
      }
    });
  }

  /** A C motion chosen on a line without its end point gets the end position recorded here. */
  private void adjustPositions(Pendant p, int cur) {
    Program prog = program(p);
    if (prog.line(cur) instanceof Instruction.Move m && m.circularEnd().orElse(null) instanceof Motion.Local end
        && prog.position(end.number()).isEmpty()) {
      p.message("C motion: TOUCHUP (SHIFT+F5 on the end point) to teach P[" + end.number() + "]");
    }
  }

  /** Inserts {@code add} before line {@code at} (a blank line at {@code at} is replaced). */
  private boolean insert(Pendant p, int at, List<Instruction> add, Map<Integer, LocalPosition> newPositions) {
    return p.editProgram(programName, pr -> ProgramEdits.insert(pr, at, add, newPositions));
  }

  // ---- POINT / TOUCHUP / POSITION ---------------------------------------------------------

  private void defaultMenu(Pendant p) {
    List<String> items = new ArrayList<>();
    for (DefaultMotion d : DefaultMotion.STANDARD) {
      items.add(d.display());
    }
    items.add("Current default: " + p.defaultMotion.display());
    items.add("ED_DEF: edit the default...");
    p.choose("POINT default", items, i -> {
      if (i < DefaultMotion.STANDARD.size()) {
        p.defaultMotion = DefaultMotion.STANDARD.get(i);
        point(p, p.defaultMotion);
      } else if (i == DefaultMotion.STANDARD.size()) {
        point(p, p.defaultMotion);
      } else {
        p.entry("Default motion (e.g. L 200mm/sec CNT50):", p.defaultMotion.display().replace(" P[]", ""), false, t -> {
          try {
            p.defaultMotion = DefaultMotion.parse(t, p.control().maxLinearSpeedMmPerSec());
            p.message("Default motion: " + p.defaultMotion.display());
            return Optional.empty();
          } catch (BadText e) {
            return Optional.of("Bad default: " + e.getMessage());
          }
        });
      }
    });
  }

  /** Records the current position as a new P[n] and inserts a motion line after the cursor. */
  private void point(Pendant p, DefaultMotion motion) {
    Program prog = program(p);
    int n = ProgramEdits.nextPositionNumber(prog);
    int uf = p.control().activeFrame(FrameKind.USER);
    int ut = p.control().activeFrame(FrameKind.TOOL);
    Position.Cartesian here = p.control().currentPose(uf, ut);
    Map<Integer, LocalPosition> add = new HashMap<>();
    add.put(n, new LocalPosition(n, "", uf, ut, here));
    if (motion.type() == Motion.Type.C) {
      add.put(n + 1, new LocalPosition(n + 1, "", uf, ut, here));
    }
    int at = Math.min(cursorLine(p), prog.lineCount()) + 1;
    if (prog.lineCount() == 0) {
      at = 1;
    }
    if (insert(p, at, List.of(motion.line(n)), add)) {
      line = at;
      field = -1;
      p.message("Position recorded to P[" + n + "]");
    }
  }

  private Optional<Motion.Target> targetUnderCursor(Program prog, int cur) {
    if (cur > prog.lineCount() || !(prog.line(cur) instanceof Instruction.Move m)) {
      return Optional.empty();
    }
    // on a C line the end point's field comes after the via point's: fields 0 type, 2 via, 4 end
    if (m.circularEnd().isPresent() && field >= 4) {
      return m.circularEnd();
    }
    return Optional.of(m.target());
  }

  private void touchup(Pendant p, Program prog, int cur) {
    Optional<Motion.Target> t = targetUnderCursor(prog, cur);
    if (t.isEmpty()) {
      p.message("TOUCHUP: the cursor is not on a motion line");
      return;
    }
    int uf = p.control().activeFrame(FrameKind.USER);
    int ut = p.control().activeFrame(FrameKind.TOOL);
    switch (t.get()) {
      case Motion.Local l -> {
        Optional<LocalPosition> old = prog.position(l.number());
        Position pos = old.isPresent() && old.get().position() instanceof Position.Joint
            ? p.control().currentJoints() : p.control().currentPose(uf, ut);
        String comment = old.map(LocalPosition::comment).orElse(l.comment());
        if (p.editProgram(programName, pr -> {
          Map<Integer, LocalPosition> pos2 = new LinkedHashMap<>(pr.positions());
          pos2.put(l.number(), new LocalPosition(l.number(), comment, uf, ut, pos));
          return ProgramEdits.with(pr, pr.lines(), pos2);
        })) {
          p.message("Position has been recorded to P[" + l.number() + "]");
        }
      }
      case Motion.Register r -> {
        if (!(r.register().index() instanceof org.robotrun.program.Index.Direct d)) {
          p.message("TOUCHUP: PR[R[i]] is indirect; record it on DATA");
          return;
        }
        Position old = p.control().registers().position(d.value());
        p.control().registers().setPosition(d.value(),
            old instanceof Position.Joint ? p.control().currentJoints() : p.control().currentPose(uf, ut));
        p.message("Position has been recorded to PR[" + d.value() + "]");
      }
    }
  }

  private void positionDetail(Pendant p, Program prog, int cur) {
    Optional<Motion.Target> t = targetUnderCursor(prog, cur);
    if (t.isEmpty()) {
      p.message("POSITION: the cursor is not on a motion line");
      return;
    }
    switch (t.get()) {
      case Motion.Local l -> {
        if (prog.position(l.number()).isEmpty()) {
          p.message("P[" + l.number() + "] is not recorded yet: TOUCHUP (SHIFT+F5) records it");
          return;
        }
        PositionScreen.openLocal(p, programName, l.number());
      }
      case Motion.Register r -> {
        if (!(r.register().index() instanceof org.robotrun.program.Index.Direct d)) {
          p.message("PR[R[i]] is indirect: see DATA");
          return;
        }
        PositionScreen.openRegister(p, d.value());
      }
    }
  }

  // ---- INST ------------------------------------------------------------------------------

  private void instMenu(Pendant p) {
    List<String> titles = InstMenu.CATEGORIES.stream().map(InstMenu.Category::title).toList();
    p.choose("INST", titles, c -> {
      InstMenu.Category cat = InstMenu.CATEGORIES.get(c);
      p.choose(cat.title(), cat.templates().stream().map(InstMenu.Template::label).toList(), i -> {
        int at = cursorLine(p);
        if (insert(p, at, cat.templates().get(i).lines().get(), Map.of())) {
          line = at;
          List<Field> fs = fields(p, program(p), at);
          field = -1;
          for (int f = 0; f < fs.size(); f++) {
            if (fs.get(f).editable()) {
              field = f;
              break;
            }
          }
          p.message("Inserted: edit the fields (RIGHT, ENTER)");
        }
      });
    });
  }

  // ---- EDCMD ------------------------------------------------------------------------------

  private void edcmd(Pendant p) {
    List<String> items = List.of("Insert", "Delete", "Copy/Cut", "Paste", "Find", "Replace", "Renumber",
        "Comment/Uncomment", "Undo");
    p.choose("EDCMD", items, i -> {
      Program prog = program(p);
      int cur = cursorLine(p);
      switch (i) {
        case 0 -> p.entry("How many lines to insert?", "1", false, t -> {
          Optional<Integer> n = Pendant.parseInt(t, 1, 99);
          if (n.isEmpty()) {
            return Optional.of("Insert: enter 1 to 99 lines, got '" + t.trim() + "'");
          }
          p.editProgram(programName, pr -> ProgramEdits.insertBlanks(pr, cur, n.get()));
          p.message(n.get() + " line(s) inserted");
          return Optional.empty();
        });
        case 1, 2 -> {
          if (cur > prog.lineCount()) {
            p.message("Nothing to select at [End]");
            return;
          }
          selectionStart = cur;
          p.message("Select lines with UP/DOWN, then " + (i == 1 ? "F4 DELETE" : "F2 COPY or F3 CUT"));
        }
        case 3 -> paste(p);
        case 4 -> find(p);
        case 5 -> replace(p);
        case 6 -> renumber(p);
        case 7 -> toggleComment(p, prog, cur);
        default -> p.undo(programName);
      }
    });
  }

  private boolean selectionKey(Pendant p, Key k, Program prog, int cur) {
    int from = Math.min(selectionStart, cur);
    int to = Math.min(Math.max(selectionStart, cur), prog.lineCount());
    switch (k) {
      case UP, DOWN -> {
        move(p, k == Key.UP ? -1 : 1);
        return true;
      }
      case F2, F3 -> {
        p.clipboard = List.copyOf(prog.lines().subList(from - 1, to));
        if (k == Key.F3) {
          deleteLines(p, from, to);
          line = from;
        }
        selectionStart = 0;
        p.message((to - from + 1) + " line(s) " + (k == Key.F2 ? "copied" : "cut"));
        return true;
      }
      case F4 -> {
        p.confirm("Delete line(s) " + from + "-" + to + "?", () -> {
          deleteLines(p, from, to);
          line = from;
          selectionStart = 0;
          p.message((to - from + 1) + " line(s) deleted");
        });
        return true;
      }
      case F5 -> {
        selectionStart = 0;
        p.message("Selection cancelled");
        return true;
      }
      default -> {
        return false;
      }
    }
  }

  private void deleteLines(Pendant p, int from, int to) {
    p.editProgram(programName, pr -> ProgramEdits.delete(pr, from, to));
  }

  private void paste(Pendant p) {
    if (p.clipboard.isEmpty()) {
      p.message("Nothing to paste: Copy/Cut lines first");
      return;
    }
    p.choose("Paste", List.of("As is (same positions)", "New position numbers", "Reverse order"), mode -> {
      int at = cursorLine(p);
      List<Instruction> clip = p.clipboard;
      if (p.editProgram(programName, pr -> ProgramEdits.paste(pr, at, clip, ProgramEdits.PasteMode.values()[mode]))) {
        p.message(clip.size() + " line(s) pasted");
      }
    });
  }

  private void find(Pendant p) {
    p.entry("Find:", findText, false, t -> {
      if (t.isBlank()) {
        return Optional.of("Find: enter the text to look for");
      }
      findText = t.trim();
      Program prog = program(p);
      int n = prog.lineCount();
      for (int k = 1; k <= n; k++) {
        int candidate = (cursorLine(p) - 1 + k) % n + 1;
        String text = TpLine.text(prog.line(candidate), prog, p.control().programNames());
        if (text.toUpperCase(Locale.ROOT).contains(findText.toUpperCase(Locale.ROOT))) {
          line = candidate;
          field = -1;
          p.message("Found '" + findText + "' at line " + candidate);
          return Optional.empty();
        }
      }
      return Optional.of("'" + findText + "' not found");
    });
  }

  private void replace(Pendant p) {
    p.entry("Replace what:", findText, false, what -> {
      if (what.isBlank()) {
        return Optional.of("Replace: enter the text to replace");
      }
      String from = what.trim();
      findText = from;
      p.entry("Replace '" + from + "' with:", "", false, with -> {
        ProgramEdits.Replaced[] done = new ProgramEdits.Replaced[1];
        p.editProgram(programName, pr -> {
          done[0] = ProgramEdits.replaceAll(pr, from, with.trim(), p.control().programNames(),
              p.control().maxLinearSpeedMmPerSec());
          return done[0].program();
        });
        if (done[0] == null) {
          return Optional.empty();
        }
        return Optional.of(done[0].replaced() + " field(s) replaced"
            + (done[0].refused() > 0 ? ", " + done[0].refused() + " not valid there" : ""));
      });
      return Optional.empty();
    });
  }

  /** Renumbers P[] in the order the lines use them (1, 2, 3…). */
  private void renumber(Pendant p) {
    boolean changed = p.editProgram(programName, ProgramEdits::renumber);
    p.message(changed ? "Positions renumbered" : "Positions already in order");
  }

  private void toggleComment(Pendant p, Program prog, int cur) {
    if (cur > prog.lineCount()) {
      p.message("Nothing to comment at [End]");
      return;
    }
    Instruction in = prog.line(cur);
    String key = programName + "\n";
    if (in instanceof Instruction.CommentedOut c) {
      Optional<Instruction> back = Optional.ofNullable(p.commentMemo.get(key + c.text()));
      if (back.isEmpty()) {
        back = p.lineParser().parse(c.text());
      }
      if (back.isEmpty()) {
        p.message("Cannot uncomment: '" + c.text() + "' is not a statement the pendant can read");
        return;
      }
      Instruction restored = back.get();
      if (p.editProgram(programName, pr -> ProgramEdits.replaceLine(pr, cur, restored))) {
        p.message("Line " + cur + " uncommented");
      }
      return;
    }
    if (in instanceof Instruction.Blank) {
      p.message("A blank line has nothing to comment out");
      return;
    }
    String text = TpLine.text(in, prog, p.control().programNames());
    p.commentMemo.put(key + text, in);
    if (p.editProgram(programName, pr -> ProgramEdits.replaceLine(pr, cur, new Instruction.CommentedOut(text)))) {
      p.message("Line " + cur + " commented out");
    }
  }
}
