package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.type.ImBoolean;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Properties;
import java.util.function.Consumer;
import org.robotrun.grade.Course;
import org.robotrun.grade.GradeResult;

/**
 * The Labs menu (docs/labs/README.md): the installed course's labs with each one's state for this
 * student (not started, in progress, handed in, the last Check my work score), opening one (its
 * own workspace in the labs folder, made from the lab's cell the first time, with its task
 * attached), and the "Lab steps" window: the current lab's numbered steps from its guide, the
 * current one marked, beside the pendant.
 *
 * <p>State lives in the labs folder: {@code ID/} is the workspace, {@code ID-handin.zip} the
 * hand-in File > Hand in suggests, and {@code .labs.properties} the last score and current step
 * of each lab (written by this panel only).
 */
public final class LabsPanel implements Workbench.MenuContributor {
  private final Course course;
  private final Path home;
  private final Optional<Course.Lab> current;
  private final Consumer<Course.Lab> open;
  private final List<String> steps;
  private final ImBoolean showSteps;
  private final Properties state = new Properties();
  private long stateReadAt;
  private String message = "";

  /**
   * @param home the student's labs folder (each lab's workspace is {@code home/ID})
   * @param current the lab this window's workspace belongs to, if any
   * @param open asked to open (switch the window to) a lab's workspace; it makes the workspace
   *     when it is new
   */
  public LabsPanel(Course course, Path home, Optional<Course.Lab> current, Consumer<Course.Lab> open) {
    this.course = course;
    this.home = home;
    this.current = current;
    this.open = open;
    this.steps = current.map(l -> steps(l.guide())).orElse(List.of());
    this.showSteps = new ImBoolean(!steps.isEmpty());
    readState();
  }

  /** The numbered steps of a guide's "## Steps" section, one string per step (continuation lines joined). */
  public static List<String> steps(Path guide) {
    List<String> out = new ArrayList<>();
    try {
      boolean in = false;
      StringBuilder step = null;
      for (String line : Files.readAllLines(guide)) {
        if (line.startsWith("## ")) {
          if (in) {
            break;
          }
          in = line.strip().equalsIgnoreCase("## Steps");
          continue;
        }
        if (!in) {
          continue;
        }
        if (line.matches("\\d+\\. .*")) {
          if (step != null) {
            out.add(step.toString());
          }
          step = new StringBuilder(unmark(line.strip()));
        } else if (step != null && line.startsWith("   ") && !line.isBlank()) {
          step.append(' ').append(unmark(line.strip()));
        } else if (step != null && line.isBlank()) {
          out.add(step.toString());
          step = null;
        }
      }
      if (step != null) {
        out.add(step.toString());
      }
    } catch (IOException | RuntimeException e) {
      out.clear();
    }
    return out;
  }

  /** A markdown emphasis like {@code *Tool Frame*} (a menu item): the asterisks around words go. */
  private static final java.util.regex.Pattern EMPHASIS =
      java.util.regex.Pattern.compile("(?<![\\w*])\\*([A-Za-z\\[][^*]*?[^\\s*])\\*(?![\\w*])");

  /** A guide's line as the steps window shows it: no markdown bold, emphasis or code marks. */
  static String unmark(String line) {
    String s = line.replace("**", "").replace("`", "");
    return EMPHASIS.matcher(s).replaceAll("$1");
  }

  /** The state of a lab for this student, in words. */
  public String stateOf(Course.Lab lab) {
    Path ws = home.resolve(lab.id());
    Path zip = home.resolve(lab.id() + "-handin.zip");
    String score = state.getProperty(lab.id() + ".score", "");
    String s;
    if (Files.isRegularFile(zip)) {
      String when;
      try {
        when = DateTimeFormatter.ofPattern("d MMM HH:mm", Locale.ROOT).withZone(ZoneId.systemDefault())
            .format(Files.getLastModifiedTime(zip).toInstant());
      } catch (IOException e) {
        when = "";
      }
      s = "handed in " + when;
    } else if (Files.isDirectory(ws)) {
      s = "in progress";
    } else {
      s = "not started";
    }
    return score.isEmpty() ? s : s + ", last check " + score;
  }

  /** Remembers the score of the last Check my work of the current lab. */
  public void checked(GradeResult r) {
    current.ifPresent(l -> {
      state.setProperty(l.id() + ".score", fmt(r.score()) + " of " + fmt(r.maxScore()));
      writeState();
    });
  }

  @Override
  public void drawMenus() {
    if (ImGui.beginMenu("Labs")) {
      if (System.currentTimeMillis() - stateReadAt > 2000) {
        readState();
      }
      Txt.disabled(course.title());
      ImGui.separator();
      for (int i = 0; i < course.labs().size(); i++) {
        Course.Lab lab = course.labs().get(i);
        boolean here = current.filter(c -> c.id().equals(lab.id())).isPresent();
        String label = (i + 1) + "  " + lab.title() + "##" + lab.id();
        if (ImGui.menuItem(label, stateOf(lab), here, !here)) {
          open.accept(lab);
        }
      }
      if (!steps.isEmpty()) {
        ImGui.separator();
        ImGui.menuItem("Lab steps", "", showSteps);
      }
      ImGui.separator();
      Txt.disabled("Your labs: " + home);
      ImGui.endMenu();
    }
  }

  /** The 3D view the Lab steps window was last placed for (display pixels); null before. */
  private WindowLayout.Rect stepsPlacedFor;
  /** Where it was placed (or last seen, once the student moved it); null before. */
  private WindowLayout.Rect stepsAt;
  /** Whether the student moved or resized it: then a resize keeps it where they put it. */
  private boolean stepsMoved;
  /** Whether it was placed with the robots' places on the screen known (the scene framed). */
  private boolean stepsSawWork;

  @Override
  public void drawPopups(WindowLayout layout) {
    drawPopups(layout, List::of);
  }

  @Override
  public void drawPopups(WindowLayout layout, java.util.function.Supplier<List<WindowLayout.Rect>> work) {
    if (!showSteps.get() || current.isEmpty()) {
      return;
    }
    Course.Lab lab = current.get();
    int at = Math.max(0, Math.min(steps.size() - 1, Integer.parseInt(state.getProperty(lab.id() + ".step", "0"))));
    float em = ImGui.getFontSize();
    float dh = ImGui.getIO().getDisplaySizeY();
    // Placed when it first shows, and again when the 3D view changes (a resize, the first-start card
    // closing) or once the scene is framed: in the corner of the 3D view that covers least of the
    // robots and parts, so neither the left column (lab 9's and 12's first steps point to its PLC and
    // Vision sections), the pendant, the card nor the arm is hidden. Once the student has moved or
    // resized it, it stays where they put it, only kept inside the window and off the pendant.
    WindowLayout.Rect target = null;
    if (stepsPlacedFor == null || !stepsPlacedFor.equals(layout.view()) || (!stepsMoved && !stepsSawWork)) {
      if (stepsMoved && stepsAt != null) {
        target = layout.keepInside(stepsAt, dh);
      } else {
        List<WindowLayout.Rect> onScreen = work.get();
        stepsSawWork = !onScreen.isEmpty();
        target = layout.labSteps(em, dh, onScreen);
      }
      if (stepsAt != null && target.equals(stepsAt) && layout.view().equals(stepsPlacedFor)) {
        target = null;  // already there
      }
      stepsPlacedFor = layout.view();
    }
    if (target != null) {
      ImGui.setNextWindowSize(target.w(), target.h(), ImGuiCond.Always);
      ImGui.setNextWindowPos(target.x(), target.y(), ImGuiCond.Always);
      stepsAt = target;
    }
    // opaque: the left column's text showed through the steps
    ImGui.setNextWindowBgAlpha(1f);
    // the lab's title inside the window, wrapped (in the title bar it was cut at the window's edge)
    if (ImGui.begin("Lab steps###labsteps", showSteps)) {
      WindowLayout.Rect seen = new WindowLayout.Rect(ImGui.getWindowPosX(), ImGui.getWindowPosY(),
          ImGui.getWindowWidth(), ImGui.getWindowHeight());
      if (stepsAt != null && target == null && !near(seen, stepsAt)) {
        stepsMoved = true;  // dragged or resized by the student
      }
      stepsAt = seen;
      ImGui.pushTextWrapPos(0);
      Txt.wrapped(lab.title());
      if (ImGui.button("< Previous") && at > 0) {
        setStep(lab, at - 1);
      }
      ImGui.sameLine();
      if (ImGui.button("Next >") && at < steps.size() - 1) {
        setStep(lab, at + 1);
      }
      String stepOf = "step " + (at + 1) + " of " + steps.size();
      // beside the buttons when it fits (in a narrow window it wrapped a letter or two a line)
      float room = ImGui.getWindowPosX() + ImGui.getWindowContentRegionMaxX() - ImGui.getItemRectMaxX();
      if (room > ImGui.calcTextSize(stepOf).x + ImGui.getStyle().getItemSpacingX() * 2) {
        ImGui.sameLine();
      }
      Txt.disabled(stepOf);
      ImGui.separator();
      for (int i = 0; i < steps.size(); i++) {
        if (i == at) {
          Txt.colored(1f, 0.85f, 0.3f, 1f, "> " + steps.get(i));
        } else {
          Txt.disabled("  " + steps.get(i));
        }
        if (ImGui.isItemClicked()) {
          setStep(lab, i);
        }
      }
      ImGui.separator();
      Txt.disabled("The whole guide: " + lab.guide());
      if (!message.isEmpty()) {
        ImGui.textUnformatted(Txt.plain(message));
      }
      ImGui.popTextWrapPos();
    }
    ImGui.end();
  }

  private static boolean near(WindowLayout.Rect a, WindowLayout.Rect b) {
    return Math.abs(a.x() - b.x()) < 1 && Math.abs(a.y() - b.y()) < 1 && Math.abs(a.w() - b.w()) < 1 && Math.abs(a.h() - b.h()) < 1;
  }

  private void setStep(Course.Lab lab, int step) {
    state.setProperty(lab.id() + ".step", Integer.toString(step));
    writeState();
  }

  private Path stateFile() {
    return home.resolve(".labs.properties");
  }

  private void readState() {
    stateReadAt = System.currentTimeMillis();
    Properties p = new Properties();
    if (Files.isRegularFile(stateFile())) {
      try (InputStream in = Files.newInputStream(stateFile())) {
        p.load(in);
      } catch (IOException | IllegalArgumentException e) {
        message = "cannot read " + stateFile() + ": " + e.getMessage();
      }
    }
    // What this window set and has not written yet stays.
    p.forEach(state::putIfAbsent);
  }

  private void writeState() {
    try {
      Files.createDirectories(home);
      Path tmp = home.resolve(".labs.properties.tmp");
      try (OutputStream out = Files.newOutputStream(tmp)) {
        state.store(out, "RobotRun labs: last Check my work score and current step per lab");
      }
      Files.move(tmp, stateFile(), java.nio.file.StandardCopyOption.REPLACE_EXISTING,
          java.nio.file.StandardCopyOption.ATOMIC_MOVE);
      message = "";
    } catch (IOException | RuntimeException e) {
      message = "cannot save the lab's state in " + stateFile() + ": " + e.getMessage();
    }
  }

  private static String fmt(double d) {
    return d == Math.rint(d) ? Long.toString((long) d) : String.format(Locale.ROOT, "%.1f", d);
  }
}
