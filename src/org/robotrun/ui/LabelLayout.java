package org.robotrun.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Places text labels beside parts of an image so that no two labels overlap, none covers a
 * label's point or an obstacle, and none leaves the image; each as near its part as it can be,
 * and off every part when there is room. A label goes to the right of its part when there is
 * room, else left, above, below or at a corner, else on rings of growing distance around its
 * point; a label that had to move away is
 * marked for a leader line to its point. A label that fits nowhere is left out (the caller lists
 * it elsewhere), so the rules above always hold.
 *
 * <p>Pure: pixels in, rectangles out (x right, y down, origin top left). Labels are placed in the
 * order given, so the first ones get the best places.
 */
public final class LabelLayout {
  private LabelLayout() {}

  /** Space between a point and its label, and between two labels (pixels). */
  public static final double GAP = 4;
  /** The half size of the square kept free around every label's point (pixels). */
  public static final double POINT_HALF = 4;
  /** Directions tried on each ring. */
  private static final int RING_DIRECTIONS = 24;

  /** A rectangle (pixels). */
  public record Box(double x, double y, double w, double h) {
    public double right() {
      return x + w;
    }

    public double bottom() {
      return y + h;
    }

    /** Shares area with {@code o} (touching edges do not count). */
    public boolean overlaps(Box o) {
      return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom();
    }

    /** Lies wholly inside a {@code width} x {@code height} image. */
    public boolean inside(double width, double height) {
      return x >= 0 && y >= 0 && right() <= width && bottom() <= height;
    }

    /** The distance from a point to this rectangle (0 inside). */
    public double distanceTo(double px, double py) {
      double dx = Math.max(Math.max(x - px, 0), px - right());
      double dy = Math.max(Math.max(y - py, 0), py - bottom());
      return Math.hypot(dx, dy);
    }

    /** The point of this rectangle nearest to {@code (px, py)}: where a leader line ends. */
    public double[] nearestPoint(double px, double py) {
      return new double[] {Math.max(x, Math.min(right(), px)), Math.max(y, Math.min(bottom(), py))};
    }

    Box grown(double by) {
      return new Box(x - by, y - by, w + 2 * by, h + 2 * by);
    }
  }

  /**
   * A label to place: its point, its text's size, and the part it names (pixels): the label goes
   * beside the part, on no other part, when there is room, else beside the point.
   */
  public record Label(double pointX, double pointY, double w, double h, Box part) {
    /** A label for a point alone. */
    public Label(double pointX, double pointY, double w, double h) {
      this(pointX, pointY, w, h, new Box(pointX - POINT_HALF, pointY - POINT_HALF, 2 * POINT_HALF, 2 * POINT_HALF));
    }
  }

  /**
   * Where a label went.
   *
   * @param box its rectangle
   * @param leader true when it is away from its point: draw a line from the point to {@link Box#nearestPoint}
   */
  public record Placed(Box box, boolean leader) {}

  /**
   * Places {@code labels} in a {@code width} x {@code height} image, keeping clear of
   * {@code obstacles}; one answer per label, in order, empty for a label that fits nowhere.
   */
  public static List<Optional<Placed>> place(List<Label> labels, double width, double height, List<Box> obstacles) {
    List<Box> points = new ArrayList<>(obstacles);
    List<Box> parts = new ArrayList<>(obstacles);
    for (Label l : labels) {
      points.add(new Box(l.pointX() - POINT_HALF, l.pointY() - POINT_HALF, 2 * POINT_HALF, 2 * POINT_HALF));
      parts.add(l.part());
      parts.add(points.get(points.size() - 1));
    }
    List<Box> labelBoxes = new ArrayList<>();
    List<Optional<Placed>> out = new ArrayList<>(labels.size());
    // first off every part, then (for a label that found no room so) off every point only
    for (Label l : labels) {
      Optional<Placed> p = placeOne(l, l.part(), width, height, parts, labelBoxes);
      p.ifPresent(x -> labelBoxes.add(x.box()));
      out.add(p);
    }
    for (int i = 0; i < labels.size(); i++) {
      if (out.get(i).isEmpty()) {
        Label l = labels.get(i);
        Optional<Placed> p = placeOne(l, points.get(obstacles.size() + i), width, height, points, labelBoxes);
        p.ifPresent(x -> labelBoxes.add(x.box()));
        out.set(i, p);
      }
    }
    return out;
  }

  private static Optional<Placed> placeOne(Label l, Box part, double width, double height, List<Box> taken,
      List<Box> labelBoxes) {
    if (!(l.w() > 0 && l.h() > 0) || l.w() > width || l.h() > height) {
      return Optional.empty();
    }
    double px = l.pointX(), py = l.pointY(), w = l.w(), h = l.h();
    double d = GAP;
    // beside the part: right, left, above, below, then the four corners
    double[][] near = {
      {part.right() + d, py - h / 2}, {part.x() - d - w, py - h / 2}, {px - w / 2, part.y() - d - h},
      {px - w / 2, part.bottom() + d}, {part.right() + d, part.y() - d - h}, {part.x() - d - w, part.y() - d - h},
      {part.right() + d, part.bottom() + d}, {part.x() - d - w, part.bottom() + d},
    };
    for (double[] c : near) {
      Box b = new Box(c[0], c[1], w, h);
      if (free(b, width, height, taken, labelBoxes)) {
        return Optional.of(new Placed(b, false));
      }
    }
    // rings of growing distance around the point, the box centred on the ring
    double step = Math.max(4, h / 2);
    double maxR = Math.hypot(width, height);
    double start = Math.hypot(part.w(), part.h()) / 2 + Math.max(w, h) / 2;
    for (double r = start; r <= maxR; r += step) {
      for (int k = 0; k < RING_DIRECTIONS; k++) {
        double a = 2 * Math.PI * k / RING_DIRECTIONS;
        Box b = new Box(px + r * Math.cos(a) - w / 2, py + r * Math.sin(a) - h / 2, w, h);
        if (free(b, width, height, taken, labelBoxes)) {
          return Optional.of(new Placed(b, true));
        }
      }
    }
    return Optional.empty();
  }

  /** Inside the image, on no obstacle or other point, and a gap away from every label already placed. */
  private static boolean free(Box b, double width, double height, List<Box> taken, List<Box> labelBoxes) {
    if (!b.inside(width, height)) {
      return false;
    }
    for (Box t : taken) {
      if (t.overlaps(b)) {
        return false;
      }
    }
    Box spaced = b.grown(GAP / 2);
    for (Box o : labelBoxes) {
      if (o.grown(GAP / 2).overlaps(spaced)) {
        return false;
      }
    }
    return true;
  }
}
