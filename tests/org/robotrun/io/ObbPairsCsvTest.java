package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.collision.Obb;
import org.robotrun.collision.bench.ObbPairGenerator;

class ObbPairsCsvTest {
  @TempDir Path dir;

  private static final String BOX = "0,0,0,1,1,1,1,0,0,0,1,0,0,0,1";

  @Test
  void writtenPairsReadBackBitForBit() throws Exception {
    List<Obb> a = new ArrayList<>();
    List<Obb> b = new ArrayList<>();
    for (ObbPairGenerator.LabeledPair p : new ObbPairGenerator(5).pairs(300)) {
      a.add(p.a());
      b.add(p.b());
    }
    Path f = dir.resolve("p.csv");
    ObbPairsCsv.write(f, a, b);
    ObbPairsCsv.Pairs read = ObbPairsCsv.read(f);
    assertThat(read.count()).isEqualTo(300);
    for (int i = 0; i < 300; i++) {
      assertThat(Obb.readFrom(read.a(), i)).isEqualTo(a.get(i));
      assertThat(Obb.readFrom(read.b(), i)).isEqualTo(b.get(i));
    }
  }

  @Test
  void errorsNameFileLineAndColumn() throws Exception {
    assertError("", ":1: empty file");
    assertError("a,b,c\n", ":1: header has 3 columns, expected 30");
    assertError(ObbPairsCsv.header() + "\n" + BOX + "," + BOX + ",1\n", ":2: expected 30 columns, got 31");
    assertError(ObbPairsCsv.header() + "\n" + BOX + "," + BOX.replace("0,0,0,1,1,1", "0,0,0,1,-1,1") + "\n",
        ":2: column b_hy: half extent must be >= 0");
    assertError(ObbPairsCsv.header() + "\n\n" + "NaN" + BOX.substring(1) + "," + BOX + "\n",
        ":3: column a_cx: expected a finite number, got NaN");
    assertError(ObbPairsCsv.header() + "\n" + BOX.replace("1,0,0,0,1,0,0,0,1", "1,0,0,0,1,0,0,0,-1") + "," + BOX + "\n",
        ":2: box a: r11..r33 is not a rotation");
  }

  private void assertError(String content, String expected) throws Exception {
    Path f = Files.writeString(dir.resolve("e.csv"), content);
    assertThatThrownBy(() -> ObbPairsCsv.read(f))
        .isInstanceOf(FileFormatException.class)
        .hasMessageStartingWith(f.toString())
        .hasMessageContaining(expected);
  }
}
