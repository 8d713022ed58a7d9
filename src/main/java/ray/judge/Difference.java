package ray.judge;

/** Where the differences between a candidate image and its reference are, with what a student should look at. */
public enum Difference {
    NONE("no difference beyond the tolerance", "nothing to fix"),
    SIZE("the image has another size than the reference",
            "check the image size the scene asks for (Width, Height) and that every pixel is written"),
    WHOLE_IMAGE("the whole image is off",
            "look at what every pixel shares: the camera (ray directions, image orientation), the light's fall-off"
                    + " (I / r^2) or the colour sum of the shading"),
    SHADOWS("only shadows differ",
            "look at the shadow test: the shadow ray's origin and direction, its offset (acne), whether it stops"
                    + " at the light, and that an occluder is tested at all"),
    EDGES("only edges differ",
            "look at anti-aliasing (n_s x n_s samples per pixel, averaged) and at where rays go through the pixel"),
    HIGHLIGHTS("only highlights differ",
            "look at the specular term: the half vector h = normalize(l + v), the exponent, and k_s (I / r^2)"),
    REGION("some regions differ",
            "look at the objects or materials where the heat map is bright: intersection (closest hit, back"
                    + " faces) or that material's shading");

    private final String summary;
    private final String advice;

    Difference(String summary, String advice) {
        this.summary = summary;
        this.advice = advice;
    }

    /** A few words: "only shadows differ". */
    public String summary() {
        return summary;
    }

    /** What to look at first. */
    public String advice() {
        return advice;
    }
}
