package ray.render;

/** Lets tests in other packages use {@link SampledRenderTest}'s scene. */
public final class SampledRenderTestAccess {
    public static final String SCENE = SampledRenderTest.SCENE;

    private SampledRenderTestAccess() {
    }
}
