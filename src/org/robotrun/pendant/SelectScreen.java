package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.program.Program;

/**
 * SELECT: the program list, alphabetical, with line counts and comments. CREATE, DELETE (with
 * confirmation), COPY, DETAIL (comment), RENAME; ENTER opens the program in the editor.
 */
final class SelectScreen implements Screen {
  private int cursor;

  @Override
  public String title(Pendant p) {
    long running = p.control().programStates().values().stream().filter(v -> !v.equals("BG")).count();
    int n = p.control().programNames().size();
    return "SELECT" + "   " + n + (n == 1 ? " program" : " programs") + (running > 1 ? "   " + running + " tasks" : "");
  }

  private String selected(Pendant p) {
    List<String> names = p.control().programNames();
    if (names.isEmpty()) {
      return null;
    }
    cursor = Math.max(0, Math.min(cursor, names.size() - 1));
    return names.get(cursor);
  }

  /** Where the comment column starts on a SELECT row ("> 12 NAME             1234 lines  "). */
  static final int COMMENT_COLUMN = 34;

  /**
   * One row per program, and its comment wrapped under the comment column onto as many rows as
   * it needs: the whole comment shows, never cut at the LCD's edge (a controller's comment is 16
   * characters; an .LS file's may be longer). The window keeps the cursor's program whole in view.
   */
  @Override
  public List<String> body(Pendant p) {
    List<String> names = p.control().programNames();
    List<String> rows = new ArrayList<>();
    if (names.isEmpty()) {
      rows.add("  (no programs: F1 CREATE)");
      return rows;
    }
    selected(p);
    java.util.Map<String, String> states = p.control().programStates();
    List<Integer> starts = new ArrayList<>();
    for (int i = 0; i < names.size(); i++) {
      Program prog = p.control().program(names.get(i)).orElseThrow();
      // a running task, a paused one or a BG logic program is marked as on the controller's list
      String state = states.get(prog.name());
      String comment = state == null ? prog.comment() : "[" + state + "] " + prog.comment();
      List<String> parts = comment.isBlank() ? List.of("") : Lcd.wrap(comment.strip(), Lcd.WIDTH - COMMENT_COLUMN);
      starts.add(rows.size());
      rows.add(String.format(Locale.ROOT, "%s%3d %-16s %4d %-5s  %s", i == cursor ? ">" : " ", i + 1, prog.name(),
          prog.lineCount(), prog.lineCount() == 1 ? "line" : "lines", parts.get(0)));
      for (String more : parts.subList(1, parts.size())) {
        rows.add(" ".repeat(COMMENT_COLUMN) + more);
      }
    }
    int start = starts.get(cursor);
    int end = cursor + 1 < starts.size() ? starts.get(cursor + 1) : rows.size();
    int top = Math.min(start, Math.max(0, end - Lcd.BODY_ROWS));
    // begin the window on a program's first row (no comment's tail without its name)
    for (int s : starts) {
      if (s >= top) {
        top = Math.min(s, start);
        break;
      }
    }
    return new ArrayList<>(rows.subList(top, Math.min(rows.size(), top + Lcd.BODY_ROWS)));
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("CREATE", "DELETE", "COPY", "DETAIL", "RENAME");
  }

  @Override
  public void key(Pendant p, Key k) {
    List<String> names = p.control().programNames();
    String sel = selected(p);
    boolean edits = k == Key.F1 || k == Key.F2 || k == Key.F3 || k == Key.F4 || k == Key.F5;
    if (edits && !p.readOnlyReason().isEmpty()) {
      // CREATE, DELETE, COPY, DETAIL (comment), RENAME: refused, nothing changes
      p.message(p.readOnlyReason());
      return;
    }
    switch (k) {
      case UP -> cursor = Math.max(0, cursor - 1);
      case DOWN -> cursor = Math.min(Math.max(0, names.size() - 1), cursor + 1);
      case ENTER -> {
        if (sel == null) {
          p.message("No programs: F1 CREATE makes one");
          return;
        }
        p.selectedProgram = sel;
        p.openEditor();
      }
      case F1 -> p.entry("Program Name:", "", true, name -> create(p, name));
      case F2 -> {
        if (sel == null) {
          p.message("Nothing to delete");
          return;
        }
        p.confirm("Delete " + sel + "?", () -> {
          Result r = p.control().deleteProgram(sel);
          switch (r) {
            case Result.Ok ok -> {
              p.message(sel + " deleted");
              if (p.selectedProgram.equals(sel)) {
                p.selectedProgram = "";
              }
            }
            case Result.Refused no -> p.message(no.reason());
          }
        });
      }
      case F3 -> {
        if (sel == null) {
          p.message("Nothing to copy");
          return;
        }
        p.entry("Copy " + sel + " to:", "", true, name -> {
          String n = name.trim().toUpperCase(Locale.ROOT);
          Optional<String> bad = checkNewName(p, n);
          if (bad.isPresent()) {
            return bad;
          }
          Program src = p.control().program(sel).orElseThrow();
          p.control().saveProgram(new Program(n, src.attributes(), src.comment(), src.lines(), src.positions()));
          p.message(sel + " copied to " + n);
          return Optional.empty();
        });
      }
      case F4 -> {
        if (sel == null) {
          p.message("No program");
          return;
        }
        Program src = p.control().program(sel).orElseThrow();
        p.entry("Comment of " + sel + ":", src.comment(), true, c -> {
          p.control().saveProgram(new Program(src.name(), src.attributes(), c.trim(), src.lines(), src.positions()));
          p.message("Comment set");
          return Optional.empty();
        });
      }
      case F5 -> {
        if (sel == null) {
          p.message("No program");
          return;
        }
        p.entry("Rename " + sel + " to:", "", true, name -> rename(p, sel, name));
      }
      default -> p.message("SELECT: UP/DOWN, ENTER opens; F1-F5 as labelled");
    }
  }

  private Optional<String> create(Pendant p, String name) {
    String n = name.trim().toUpperCase(Locale.ROOT);
    Optional<String> bad = checkNewName(p, n);
    if (bad.isPresent()) {
      return bad;
    }
    p.control().saveProgram(Program.of(n, List.of()));
    cursor = p.control().programNames().indexOf(n);
    p.selectedProgram = n;
    p.openEditor();
    p.message(n + " created");
    return Optional.empty();
  }

  private Optional<String> rename(Pendant p, String from, String name) {
    String n = name.trim().toUpperCase(Locale.ROOT);
    Optional<String> bad = checkNewName(p, n);
    if (bad.isPresent()) {
      return bad;
    }
    Program src = p.control().program(from).orElseThrow();
    Result r = p.control().deleteProgram(from);
    if (r instanceof Result.Refused no) {
      return Optional.of("Cannot rename: " + no.reason());
    }
    p.control().saveProgram(new Program(n, src.attributes(), src.comment(), src.lines(), src.positions()));
    if (p.selectedProgram.equals(from)) {
      p.selectedProgram = n;
    }
    p.message(from + " renamed to " + n);
    return Optional.empty();
  }

  static Optional<String> checkNewName(Pendant p, String n) {
    if (!Program.isValidName(n)) {
      return Optional.of("Bad name '" + n + "': letters, digits, _; a letter first; up to "
          + Program.MAX_NAME_LENGTH + " chars");
    }
    if (p.control().program(n).isPresent()) {
      return Optional.of("Name " + n + " is already taken");
    }
    return Optional.empty();
  }
}
