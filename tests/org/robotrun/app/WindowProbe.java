package org.robotrun.app;

import static org.lwjgl.glfw.GLFW.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.robotrun.sim.DrawItem;
import org.robotrun.ui.PendantPanel;
import org.robotrun.ui.SceneBounds;
import org.robotrun.ui.WindowLayout;
import org.robotrun.ui.WindowSettings;

/**
 * Runs the real window (in a child JVM on an X server, started by {@link WindowLayoutXvfbTest})
 * and writes what it drew: for each window size in turn, the layout's rectangles, every pendant
 * key's rectangle and the robot's projected bounding box, in display pixels. With {@code --add-box},
 * it then clicks the cell editor's "Add box" and "Save" buttons with xdotool, as a student would.
 *
 * <p>Arguments: {@code OUT SCENARIO CONFIGDIR [--add-box] W1xH1 W2xH2 ...}
 */
public final class WindowProbe {
  private WindowProbe() {}

  public static void main(String[] args) throws Exception {
    Path out = Path.of(args[0]);
    Path scenario = Path.of(args[1]);
    Path config = Path.of(args[2]);
    boolean addBox = false;
    List<int[]> sizes = new ArrayList<>();
    for (int i = 3; i < args.length; i++) {
      if (args[i].equals("--add-box")) {
        addBox = true;
      } else {
        String[] wh = args[i].split("x");
        sizes.add(new int[] {Integer.parseInt(wh[0]), Integer.parseInt(wh[1])});
      }
    }
    int[] first = sizes.get(0);
    var s = GuiCommand.open(scenario, first[0], first[1], new WindowSettings(Optional.of(config)));
    List<String> lines = new ArrayList<>();
    int[] frame = {0};
    int[] step = {0};
    boolean clicks = addBox;
    int[] clickStage = {0};
    long handle = s.window().handle();
    s.window().setAfterFrameHandler(() -> {
      frame[0]++;
      // the window sleeps when idle; the probe wants the next frame now
      glfwPostEmptyEvent();
      if (step[0] < sizes.size()) {
        // a few frames at each size so the layout settles, then record it
        if (frame[0] % 6 == 5) {
          record(s, lines, sizes.get(step[0]));
          step[0]++;
          if (step[0] < sizes.size()) {
            glfwSetWindowSize(handle, sizes.get(step[0])[0], sizes.get(step[0])[1]);
          }
        }
        return;
      }
      if (!clicks || clickStage[0] >= 4) {
        s.window().close(true);
        return;
      }
      if (frame[0] % 6 != 0) {
        return;
      }
      var panel = s.bench().editorPanel();
      s.bench().layoutState().sidebarVisible = true;
      s.bench().layoutState().editorOpen = true;
      s.bench().layoutState().robotOpen = false;
      s.bench().layoutState().cellOpen = false;
      s.bench().layoutState().taskOpen = false;
      s.bench().help().showWelcome(false);
      switch (clickStage[0]) {
        case 0 -> clickStage[0]++;  // one frame for the editor to show
        case 1 -> {
          panel.buttonRect("Add box").ifPresent(r -> click(handle, r));
          clickStage[0]++;
        }
        case 2 -> {
          lines.add("objects " + String.join(",", s.editor().world().objects().stream().map(o -> o.name()).toList()));
          panel.buttonRect("Save").ifPresent(r -> click(handle, r));
          clickStage[0]++;
        }
        default -> {
          lines.add("message " + panel.message());
          clickStage[0]++;
        }
      }
    });
    GuiCommand.run(s);
    s.window().close();
    Files.write(out, lines, StandardCharsets.UTF_8);
  }

  private static void click(long handle, float[] r) {
    int[] wx = new int[1], wy = new int[1];
    glfwGetWindowPos(handle, wx, wy);
    int x = Math.round(wx[0] + r[0] + r[2] / 2), y = Math.round(wy[0] + r[1] + r[3] / 2);
    try {
      new ProcessBuilder("xdotool", "mousemove", "--sync", String.valueOf(x), String.valueOf(y), "click", "1")
          .inheritIO().start().waitFor();
    } catch (IOException e) {
      throw new IllegalStateException("xdotool: " + e.getMessage(), e);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  private static void record(GuiCommand.Session s, List<String> lines, int[] size) {
    WindowLayout l = s.bench().layout();
    int[] ww = new int[1], wh = new int[1], fw = new int[1], fh = new int[1];
    glfwGetWindowSize(s.window().handle(), ww, wh);
    glfwGetFramebufferSize(s.window().handle(), fw, fh);
    lines.add(String.format(Locale.ROOT, "size %d %d asked %d %d", ww[0], wh[0], size[0], size[1]));
    lines.add(rect("menu", l.menuBar()));
    lines.add(rect("sidebar", l.sidebar()));
    lines.add(rect("view", l.view()));
    lines.add(rect("pendant", l.pendant()));
    lines.add(rect("card", s.bench().help().welcomeRect()));
    for (PendantPanel.KeyRect k : s.bench().pendantPanel().drawnKeys()) {
      lines.add(String.format(Locale.ROOT, "key %s %.1f %.1f %.1f %.1f", k.key().name(), k.x(), k.y(), k.w(), k.h()));
    }
    // the robot's bounding box, projected (corners of each link's box at its reach)
    Matrix4f vp = s.window().camera().viewProjection(fw[0], fh[0]);
    float x0 = Float.MAX_VALUE, y0 = Float.MAX_VALUE, x1 = -Float.MAX_VALUE, y1 = -Float.MAX_VALUE;
    String robot = s.controller().name() + "/";
    for (DrawItem it : s.sim().snapshot().scene().items()) {
      if (!it.name().startsWith(robot)) {
        continue;
      }
      List<org.joml.Vector3f> pts = new ArrayList<>();
      SceneBounds.addCorners(it, pts);
      for (var p : pts) {
        Vector4f c = new Vector4f(p, 1).mul(vp);
        float sx = (c.x / c.w * 0.5f + 0.5f) * ww[0], sy = (0.5f - c.y / c.w * 0.5f) * wh[0];
        x0 = Math.min(x0, sx);
        y0 = Math.min(y0, sy);
        x1 = Math.max(x1, sx);
        y1 = Math.max(y1, sy);
      }
    }
    lines.add(String.format(Locale.ROOT, "robot %.1f %.1f %.1f %.1f", x0, y0, x1 - x0, y1 - y0));
  }

  private static String rect(String name, WindowLayout.Rect r) {
    return String.format(Locale.ROOT, "%s %.1f %.1f %.1f %.1f", name, r.x(), r.y(), r.w(), r.h());
  }
}
