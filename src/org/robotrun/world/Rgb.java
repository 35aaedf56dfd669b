package org.robotrun.world;

import java.util.Locale;
import java.util.Optional;

/** A display colour, 8 bits per channel; files write it as {@code "#rrggbb"}. */
public record Rgb(int red, int green, int blue) {
  public static final Rgb GREY = new Rgb(0x80, 0x80, 0x80);

  public Rgb {
    if ((red | green | blue) < 0 || red > 255 || green > 255 || blue > 255) {
      throw new IllegalArgumentException("colour channels are 0..255");
    }
  }

  /** Parses {@code "#rrggbb"}; empty when the text is not of that form. */
  public static Optional<Rgb> parse(String hex) {
    if (hex.length() != 7 || hex.charAt(0) != '#') {
      return Optional.empty();
    }
    try {
      int v = Integer.parseInt(hex.substring(1), 16);
      return Optional.of(new Rgb(v >> 16 & 0xFF, v >> 8 & 0xFF, v & 0xFF));
    } catch (NumberFormatException e) {
      return Optional.empty();
    }
  }

  public String hex() {
    return String.format(Locale.ROOT, "#%02x%02x%02x", red, green, blue);
  }
}
