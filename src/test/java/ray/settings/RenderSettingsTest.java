package ray.settings;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.RayKind;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.plan.RenderPlan;
import ray.render.Renderer;

/**
 * One immutable settings value, resolved once from the scene's globals and then the caller's overrides,
 * validated by one table: the parser, the settings and the command line accept exactly the table's
 * ranges; a render with overrides leaves the parsed scene as it was; the plan sees the overrides.
 */
class RenderSettingsTest {

    private static final String SCENE = "Width 8\nHeight 6\nAASamples 2\nMaxDepth 5\nSampler jittered\nTargetError 2\n\n"
            + "Camera Camera\n\nMaterial Glazed m\n\nSurface Sphere\nref material m\n\n";

    private static Scene parse(String text) throws SceneFormatException {
        return Parser.parse(text, "s.txt", new ArrayList<>());
    }

    @Test
    void settersReturnNewValuesAndLeaveTheOriginal() {
        RenderSettings a = new RenderSettings();
        RenderSettings b = a.samples(3).sampler("sobol").maxDepth(2).targetError(1).seed(7).progressive(true).cutFaint(true);
        assertFalse(a.resolved());
        assertTrue(b.resolved());
        assertEquals(new RenderSettings(), a, "the original is unchanged");
        assertEquals(3, b.samples());
        assertEquals("sobol", b.sampler());
        assertThrows(IllegalStateException.class, a::samples, "an unresolved value has no n_s of its own");
    }

    @Test
    void resolvingTakesTheScenesGlobalsWhereNothingIsSet() throws Exception {
        Scene s = parse(SCENE);
        RenderSettings own = RenderSettings.of(s);
        assertEquals("jittered", own.sampler());
        assertEquals(2, own.samples());
        assertEquals(5, own.maxDepth());
        assertEquals(2.0, own.targetError());
        RenderSettings over = new RenderSettings().samples(4).maxDepth(0).resolve(s);
        assertEquals(4, over.samples());
        assertEquals(0, over.maxDepth());
        assertEquals("jittered", over.sampler(), "what is not overridden comes from the scene");
        assertEquals(over, over.resolve(new Scene()), "a resolved value resolves to itself");
    }

    /** The renderer used to write MaxDepth into the scene for a render; the plan never saw an AASamples override. */
    @Test
    void aRenderWithOverridesLeavesTheSceneAndThePlanFollowsThem() throws Exception {
        Scene s = parse(SCENE.replace("Sampler jittered\n", ""));
        Renderer r = new Renderer(s).settings(new RenderSettings().samples(3).maxDepth(1)).threads(1);
        r.render();
        assertEquals(2, s.samplesPerPixel);
        assertEquals(5, s.maxDepth);
        assertEquals(8 * 6 * 9, r.stats().get(RayKind.CAMERA));
        assertEquals(8 * 6 * 9, r.plan().bound().get(RayKind.CAMERA), "the plan counts the override's samples");
        assertEquals(1, r.plan().settings().maxDepth());
        assertTrue(r.stats().get(RayKind.MIRROR) <= r.plan().bound().get(RayKind.MIRROR));
        RenderPlan own = RenderPlan.derive(s, new RenderSettings());
        assertEquals(8 * 6 * 4, own.bound().get(RayKind.CAMERA));
    }

    /** Every row's range is what the scene file, the settings and the command line accept: its ends in, one step beyond out. */
    @Test
    void theTableIsWhatEveryEntryPointAccepts() throws Exception {
        for (RenderOption o : RenderOption.values()) {
            if (o.type == RenderOption.Type.CHOICE) {
                for (String c : o.choices) {
                    assertEquals(c, parse(SCENE.replace("Sampler jittered", o.global + " " + c)).sampler);
                    assertNull(o.problem(o.option, c));
                }
                assertThrows(SceneFormatException.class, () -> parse(SCENE.replace("Sampler jittered", o.global + " Grid")));
                assertThrows(IllegalArgumentException.class, () -> new RenderSettings().sampler("Grid"));
                assertEquals(o.option + " must be " + o.expected() + ", got 'Grid'", o.problem(o.option, "Grid"));
                continue;
            }
            double step = o.type == RenderOption.Type.INT ? 1 : 1e-9;
            for (double v : new double[] {o.min, o.max}) {
                parse(withGlobal(o, format(o, v)));
                assertNull(o.problem(o.option, v));
                set(o, v);
            }
            for (double v : new double[] {o.min - step, o.max + step}) {
                String text = withGlobal(o, format(o, v));
                assertThrows(SceneFormatException.class, () -> parse(text), o.global + " " + v);
                assertTrue(o.problem(o.option, v).startsWith(o.option + " must be "), o.problem(o.option, v));
                assertThrows(IllegalArgumentException.class, () -> set(o, v), o.global + " " + v);
            }
        }
    }

    private static String withGlobal(RenderOption o, String value) {
        String base = SCENE.replaceAll("(?m)^" + o.global + " .*\n", "");
        return o.global + " " + value + "\n" + base;
    }

    private static String format(RenderOption o, double v) {
        return o.type == RenderOption.Type.INT ? Long.toString((long) v) : Double.toString(v);
    }

    private static RenderSettings set(RenderOption o, double v) {
        RenderSettings s = new RenderSettings();
        return switch (o) {
            case SAMPLES -> s.samples((int) v);
            case MAX_DEPTH -> s.maxDepth((int) v);
            case TARGET_ERROR -> s.targetError(v);
            default -> throw new AssertionError(o);
        };
    }
}
