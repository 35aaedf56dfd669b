package org.robotrun.io;

/** A hand-in that cannot be written or read; the message names the file and the reason. */
public final class HandInException extends Exception {
  public HandInException(String message) {
    super(message);
  }
}
