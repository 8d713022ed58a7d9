package ray.plan;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.plan.PlanFixture.assertSameImage;
import static ray.plan.PlanFixture.assertWithinBound;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import ray.RayKind;
import ray.Scene;
import ray.parse.Parser;

/** Every scene in scenes/, at a quarter of its size: the same image with and without the plan's skips. */
class PlanScenesTest {

    static Stream<Path> scenes() throws IOException {
        return Files.list(Path.of("scenes")).filter(p -> p.toString().endsWith(".txt")).sorted();
    }

    private static Scene small(Path p) throws Exception {
        Scene s = Parser.parse(p, new ArrayList<>());
        if (Double.isNaN(s.camera.aspect)) {
            s.camera.aspect = (double) s.width / s.height;   // keep the view the full-size image has
        }
        s.width = Math.max(1, s.width / 4);
        s.height = Math.max(1, s.height / 4);
        return s;
    }

    @ParameterizedTest
    @MethodSource("scenes")
    void sameImageWithAndWithoutTheSkips(Path p) throws Exception {
        PlanFixture with = PlanFixture.render(small(p), java.util.EnumSet.allOf(Skip.class));
        PlanFixture without = PlanFixture.render(small(p), RenderPlan.NO_SKIPS);
        assertSameImage(with.image, without.image, p.toString());
        assertWithinBound(with.stats, with.plan.bound(), p + " with the plan");
        assertWithinBound(without.stats, without.plan.bound(), p + " without the plan's skips");
        for (RayKind k : RayKind.values()) {
            assertTrue(with.rays(k) <= without.rays(k), p + ": the plan cast more " + k.key() + " rays than no plan");
        }
    }
}
