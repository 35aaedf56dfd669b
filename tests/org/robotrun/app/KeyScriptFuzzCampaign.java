package org.robotrun.app;

import java.util.List;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** The long key-script campaign: only with {@code ./mvnw verify -Pfuzz} (docs/fuzzing.md); random seed. */
class KeyScriptFuzzCampaign extends KeyScriptFuzzTest {
  @Override
  @Provide
  Arbitrary<List<String>> scripts() {
    return super.scripts();
  }

  @Property(tries = 5_000)
  void campaign(@ForAll("scripts") List<String> lines) {
    check(lines);
  }
}
