package org.robotrun.motion;

/** The coordinate system of the jog keys, as the pendant's COORD key selects it. */
public enum JogFrame {
  /** Each key pair moves one joint. */
  JOINT,
  /** Translation along / rotation about the active jog frame's axes (JOGFRAME[n]), through the TCP. */
  JGFRM,
  /** Translation along / rotation about WORLD's axes, through the TCP. */
  WORLD,
  /** Translation along / rotation about the active tool frame's axes, through the TCP. */
  TOOL,
  /** Translation along / rotation about the active user frame's axes, through the TCP. */
  USER
}
