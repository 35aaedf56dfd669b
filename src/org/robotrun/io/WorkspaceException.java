package org.robotrun.io;

/** A workspace that cannot be opened or created; the message names the folder and the reason. */
public final class WorkspaceException extends Exception {
  public WorkspaceException(String message) {
    super(message);
  }
}
