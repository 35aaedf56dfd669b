package org.robotrun.render;

import java.util.List;
import org.joml.Matrix4f;
import org.robotrun.sim.DrawItem;

/**
 * Which of a scene's items the window keeps in its still layer, and when the layer must be drawn
 * again (the bookkeeping of {@link SceneRenderer#prepareRetained}; no GL). Items are matched by
 * their place in the snapshot's list, frame to frame. The layer is drawn again when the view
 * changes (camera, the view's rectangle, the window's size, the floor), when the number of items
 * changes, when an item in the layer changes in any way (moves, changes colour: a collision's
 * highlight, a selection, the driven robot's tint, a part taken), and when an item left out has
 * stood still for {@link #STILL_FRAMES_TO_SETTLE} frames. A redrawn layer holds the opaque items
 * that did not change since the last frame; translucent items are never in it.
 */
final class StillLayer {
  /** Frames an item left out of the layer must stand still before the layer is drawn again with it. */
  static final int STILL_FRAMES_TO_SETTLE = 30;

  /** What the view is: the layer is drawn again whenever it changes. */
  record View(int width, int height, int x, int y, int w, int h, double floorZ, Matrix4f viewProj) {
    View {
      viewProj = new Matrix4f(viewProj);
    }
  }

  /**
   * One frame's decision.
   *
   * @param rebuild draw the layer again (then the whole view is damaged)
   * @param inLayer per item: drawn in the layer (else drawn over it every time)
   * @param movedOutside an item left out of the layer changed since the last frame (its
   *     rectangle, last frame's and this one's, is damaged)
   */
  record Plan(boolean rebuild, boolean[] inLayer, boolean movedOutside) {}

  private View layerView;
  private List<DrawItem> layerItems = List.of();
  private boolean[] inLayer = new boolean[0];
  private List<DrawItem> lastItems;
  private int[] stillFrames = new int[0];

  /** Decides for this frame's items seen in this view, and remembers them for the next frame. */
  Plan next(List<DrawItem> items, View view) {
    boolean sameCount = lastItems != null && lastItems.size() == items.size();
    if (stillFrames.length != items.size()) {
      stillFrames = new int[items.size()];
    }
    boolean[] moved = new boolean[items.size()];
    for (int i = 0; i < items.size(); i++) {
      moved[i] = sameCount && !items.get(i).equals(lastItems.get(i));
      stillFrames[i] = moved[i] || !sameCount ? 0 : Math.min(stillFrames[i] + 1, STILL_FRAMES_TO_SETTLE);
    }
    boolean rebuild = !view.equals(layerView) || layerItems.size() != items.size();
    for (int i = 0; i < items.size() && !rebuild; i++) {
      if (inLayer[i] ? !items.get(i).equals(layerItems.get(i))
          : opaque(items.get(i)) && stillFrames[i] >= STILL_FRAMES_TO_SETTLE) {
        rebuild = true;
      }
    }
    if (rebuild) {
      boolean[] keep = new boolean[items.size()];
      for (int i = 0; i < items.size(); i++) {
        keep[i] = opaque(items.get(i)) && !moved[i];
      }
      layerView = view;
      layerItems = items;
      inLayer = keep;
    }
    boolean movedOutside = false;
    for (int i = 0; i < items.size(); i++) {
      movedOutside |= !inLayer[i] && (moved[i] || !sameCount);
    }
    lastItems = items;
    return new Plan(rebuild, inLayer.clone(), movedOutside);
  }

  static boolean opaque(DrawItem item) {
    return item.color().a() >= 1f;
  }
}
