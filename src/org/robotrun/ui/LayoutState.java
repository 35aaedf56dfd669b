package org.robotrun.ui;

import java.util.Properties;

/**
 * What the student chose about the window's layout: which panels show and how wide the side
 * columns are. Small and plain so a workspace can keep one per cell ({@link #toProperties} /
 * {@link #fromProperties}); the window keeps the last one in the user's settings folder until then.
 * Widths are in unscaled pixels (multiplied by the monitor's content scale when drawn); 0 means
 * "the natural width".
 */
public final class LayoutState {
  public boolean pendantVisible = true;
  /** The left column (task, robot, cell, cell editor); null: decide by window width. */
  public Boolean sidebarVisible;
  public float pendantWidth;
  public float sidebarWidth;
  /** The first-start card was closed (it comes back from Help). */
  public boolean welcomeSeen;
  public boolean taskOpen = true;
  public boolean robotOpen = true;
  public boolean cellOpen = true;
  public boolean editorOpen;
  /**
   * The panels the student showed or hid in the View menu ({@link PanelRules.Panel#key} to shown);
   * a panel not in it follows {@link PanelRules}.
   */
  public final java.util.Map<String, Boolean> panels = new java.util.TreeMap<>();

  /** Back to the default layout (Help's first-start card stays dismissed). */
  public void reset() {
    pendantVisible = true;
    sidebarVisible = null;
    pendantWidth = 0;
    sidebarWidth = 0;
    taskOpen = true;
    robotOpen = true;
    cellOpen = true;
    editorOpen = false;
    panels.clear();
  }

  public Properties toProperties() {
    Properties p = new Properties();
    p.setProperty("pendantVisible", Boolean.toString(pendantVisible));
    if (sidebarVisible != null) {
      p.setProperty("sidebarVisible", sidebarVisible.toString());
    }
    p.setProperty("pendantWidth", Float.toString(pendantWidth));
    p.setProperty("sidebarWidth", Float.toString(sidebarWidth));
    p.setProperty("welcomeSeen", Boolean.toString(welcomeSeen));
    p.setProperty("taskOpen", Boolean.toString(taskOpen));
    p.setProperty("robotOpen", Boolean.toString(robotOpen));
    p.setProperty("cellOpen", Boolean.toString(cellOpen));
    p.setProperty("editorOpen", Boolean.toString(editorOpen));
    panels.forEach((k, v) -> p.setProperty("panel." + k, Boolean.toString(v)));
    return p;
  }

  /** Reads what {@link #toProperties} wrote; a missing or unreadable entry keeps its default. */
  public static LayoutState fromProperties(Properties p) {
    LayoutState s = new LayoutState();
    s.pendantVisible = bool(p, "pendantVisible", true);
    String side = p.getProperty("sidebarVisible");
    s.sidebarVisible = side == null ? null : Boolean.parseBoolean(side);
    s.pendantWidth = width(p, "pendantWidth");
    s.sidebarWidth = width(p, "sidebarWidth");
    s.welcomeSeen = bool(p, "welcomeSeen", false);
    s.taskOpen = bool(p, "taskOpen", true);
    s.robotOpen = bool(p, "robotOpen", true);
    s.cellOpen = bool(p, "cellOpen", true);
    s.editorOpen = bool(p, "editorOpen", false);
    for (PanelRules.Panel panel : PanelRules.Panel.values()) {
      String v = p.getProperty("panel." + panel.key());
      if (v != null && (v.trim().equals("true") || v.trim().equals("false"))) {
        s.panels.put(panel.key(), Boolean.parseBoolean(v.trim()));
      }
    }
    return s;
  }

  private static boolean bool(Properties p, String key, boolean dflt) {
    String v = p.getProperty(key);
    return v == null ? dflt : Boolean.parseBoolean(v.trim());
  }

  private static float width(Properties p, String key) {
    try {
      float f = Float.parseFloat(p.getProperty(key, "0").trim());
      return Float.isFinite(f) && f >= 0 && f <= 10_000 ? f : 0;
    } catch (NumberFormatException e) {
      return 0;
    }
  }
}
