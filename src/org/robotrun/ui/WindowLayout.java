package org.robotrun.ui;

import java.util.List;

/**
 * Where the window's parts go, computed fresh every frame from the window size, so shrinking
 * and growing the window never leaves panels piled over the scene. Side by side, never on top of
 * each other: the main menu bar across the top, the left column (task, robot, cell, editor), the
 * 3D view in the middle, the teach pendant on the right at its natural width. When the window is
 * too narrow for all three, the pendant keeps its width, the left column goes first and the 3D view
 * keeps at least {@link #MIN_VIEW_FRACTION} of the width.
 *
 * <p>All sizes in ImGui display pixels (y down, origin top left).
 */
public record WindowLayout(Rect menuBar, Rect sidebar, Rect view, Rect pendant) {
  /** The 3D view never gets less than this part of the window's width. */
  public static final float MIN_VIEW_FRACTION = 0.35f;
  /** The left column's default width (unscaled pixels). */
  public static final float SIDEBAR_WIDTH = 270;
  /**
   * The first-start card may take up to this part of the 3D view's height (it grows to its text; at
   * 1024x640 with a lab's task 0.45 was too little and the card's last lines sat under its scroll bar).
   */
  public static final float WELCOME_MAX_FRACTION = 0.6f;
  /** Below this window width (unscaled) the left column starts hidden. */
  public static final float SIDEBAR_MIN_WINDOW = 1200;

  /** A rectangle in display pixels; width or height 0 means hidden. */
  public record Rect(float x, float y, float w, float h) {
    public boolean visible() {
      return w > 0 && h > 0;
    }

    public float right() {
      return x + w;
    }

    public float bottom() {
      return y + h;
    }

    public boolean contains(float px, float py) {
      return px >= x && px < x + w && py >= y && py < y + h;
    }

    public boolean overlaps(Rect o) {
      return visible() && o.visible() && x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }

    /** The area this rectangle and {@code o} share (square pixels; 0 when apart). */
    public double overlapArea(Rect o) {
      if (!overlaps(o)) {
        return 0;
      }
      return (double) (Math.min(right(), o.right()) - Math.max(x, o.x)) * (Math.min(bottom(), o.bottom()) - Math.max(y, o.y));
    }
  }

  /**
   * The smallest window (display pixels, width then height) in which the pendant shows whole: its
   * natural width beside the 3D view's {@link #MIN_VIEW_FRACTION}, and the height its keys need
   * under the menu bar.
   */
  public static int[] minimumSize(float menuBarHeight, float pendantNaturalWidth, float pendantMinimumHeight) {
    return new int[] {
      (int) Math.ceil(pendantNaturalWidth / (1 - MIN_VIEW_FRACTION)),
      (int) Math.ceil(menuBarHeight + pendantMinimumHeight)};
  }

  /**
   * @param width window width (display pixels)
   * @param height window height (display pixels)
   * @param menuBarHeight height of the main menu bar
   * @param scale the monitor's content scale (1 on an ordinary screen, 2 on a HiDPI one)
   * @param pendantNaturalWidth the pendant's width when all its keys show (display pixels)
   */
  public static WindowLayout compute(float width, float height, float menuBarHeight, float scale,
      float pendantNaturalWidth, LayoutState state) {
    float top = menuBarHeight;
    float h = Math.max(0, height - top);
    float pw = 0;
    if (state.pendantVisible) {
      pw = state.pendantWidth > 0 ? state.pendantWidth * scale : pendantNaturalWidth;
      pw = Math.max(pendantNaturalWidth * 0.6f, pw);
      pw = Math.min(pw, width * (1 - MIN_VIEW_FRACTION));
    }
    boolean side = state.sidebarVisible != null ? state.sidebarVisible : width >= SIDEBAR_MIN_WINDOW * scale;
    float sw = 0;
    if (side) {
      sw = (state.sidebarWidth > 0 ? state.sidebarWidth : SIDEBAR_WIDTH) * scale;
      sw = Math.max(0, Math.min(sw, width - pw - width * MIN_VIEW_FRACTION));
    }
    float vw = Math.max(0, width - pw - sw);
    return new WindowLayout(
        new Rect(0, 0, width, top),
        new Rect(0, top, sw, sw > 0 ? h : 0),
        new Rect(sw, top, vw, h),
        new Rect(width - pw, top, pw, pw > 0 ? h : 0));
  }

  /**
   * Where the "Lab steps" window first opens (display pixels): the top right corner of the 3D view,
   * so that it covers neither the left column (lab steps point to its Vision, PLC and robot sections)
   * nor the pendant, nor the first-start card docked along the view's bottom. This layout's view is
   * the one above that card; {@code windowHeight} is the whole window's height.
   *
   * @param em the font size (display pixels)
   */
  public Rect labSteps(float em, float windowHeight) {
    return labSteps(em, windowHeight, List.of());
  }

  /**
   * Where the "Lab steps" window opens: the corner of the 3D view that hides least of
   * {@code work} (the screen rectangles of the robots and the parts, display pixels; each counts by
   * the part of it hidden, so a whole small part weighs as much as a whole arm), top right
   * first, then top left, bottom right, bottom left. In a corner it never covers the left column,
   * the pendant or the first-start card; among the corners it keeps off the arm the student
   * watches (in lab 11 the top right one hid robot2 at 1366x768).
   */
  public Rect labSteps(float em, float windowHeight, List<Rect> work) {
    // half the view, but in a small window at least 15 em where the view has them (at the window's
    // minimum size half the view was 134 px: the buttons were cut and the steps a word a line)
    float w = Math.min(em * 21, Math.max(view.w * 0.5f, Math.min(view.w, em * 15)));
    float h = Math.min(windowHeight * 0.45f, view.h);
    Rect best = null;
    double bestCover = Double.POSITIVE_INFINITY;
    for (Rect c : List.of(new Rect(view.right() - w, view.y, w, h), new Rect(view.x, view.y, w, h),
        new Rect(view.right() - w, view.bottom() - h, w, h), new Rect(view.x, view.bottom() - h, w, h))) {
      double cover = 0;
      for (Rect r : work) {
        // each thing counts by how much of it is hidden: a whole small part weighs as much as a whole arm
        cover += c.overlapArea(r) / Math.max(1.0, (double) r.w * r.h);
      }
      if (cover < bestCover) {
        best = c;
        bestCover = cover;
      }
    }
    return best;
  }

  /**
   * Where a window the student placed ({@code placed}) goes after the main window changed size:
   * where it was, only moved (and, wider than the room, narrowed) so that it stays in the window
   * under the menu bar and off the pendant. The student's placement is kept; the pendant's keys
   * stay usable.
   *
   * @param windowHeight the whole window's height (display pixels)
   */
  public Rect keepInside(Rect placed, float windowHeight) {
    float right = pendant.visible() ? pendant.x : menuBar.w;
    float top = menuBar.bottom();
    float w = Math.max(1, Math.min(placed.w, right));
    float h = Math.max(1, Math.min(placed.h, windowHeight - top));
    float x = Math.max(0, Math.min(placed.x, right - w));
    float y = Math.max(top, Math.min(placed.y, windowHeight - h));
    return new Rect(x, y, w, h);
  }

  /**
   * How many columns the first-start card lays its steps out in for a view {@code viewWidth} wide:
   * each column at least {@code em * 12} wide, so that no step wraps into a tall narrow strip (at
   * 1024x640 four narrow columns made the card taller than its room and cut its last line).
   */
  public static int welcomeColumns(float viewWidth, float em, boolean hasTask) {
    if (hasTask && viewWidth >= em * 56) {
      return 4;
    }
    return viewWidth >= em * 36 ? 3 : 1;
  }
}
