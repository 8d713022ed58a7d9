/**
 * Test helper in the default package: NOT a scene class, with a static initialiser that leaves a
 * trace. Naming it in a scene must give the "not a Surface" error without ever running that
 * initialiser (ParserTest checks the property stays unset).
 */
public class EvilNotASurface {

    public static final String RAN = "raytracer.test.EvilNotASurface.initialised";

    public double radius;

    static {
        System.setProperty(RAN, "true");
    }

    public EvilNotASurface() {
    }
}
