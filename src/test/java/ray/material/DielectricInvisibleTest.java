package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import ray.parse.Parser;
import ray.render.Image;

/**
 * A dielectric of refractive index 1 with exact Fresnel and no attenuation changes nothing a ray
 * carries: R = 0 exactly, so no reflected ray, and the refracted ray goes on with the same colour. It
 * must render as the scene without it, whatever closed surface it is made of.
 *
 * <p>Tolerance: the refracted direction is rebuilt as eta d + (eta cosI - cosT) n with cosT =
 * sqrt(1 - (1 - cosI^2)), which differs from cosI by a few ulps, and each crossing moves the origin by
 * the hit point's error bound (about 1e-15 here). A point seen behind the ball therefore moves by
 * about 1e-14 of the scene's size, and its colour (smooth in the point, apart from silhouettes and
 * shadow edges) by about as much. So every linear channel must agree within 1e-9; a wrong model (any
 * reflection, any bending, any loss) changes pixels by 1e-3 or more. A dielectric blocks shadow rays,
 * as the contract says, so the glass is placed where its shadow falls beyond the floor's front edge
 * (z = 1), on nothing the camera sees.
 */
class DielectricInvisibleTest {

    static final String SCENE = """
            Width 64
            Height 48
            MaxDepth 6
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.2 0.2 0.2]

            Camera Camera
            Vector3d eye [0 1 8]
            Vector3d target [0 0 0]

            Material BlinnPhong red
            Vector3d ambientColor [0.3 0.05 0.05]
            Vector3d diffuseColor [0.8 0.2 0.2]

            Material Diffuse floor
            Vector3d ambientColor [0.2 0.2 0.2]
            Vector3d diffuseColor [0.6 0.6 0.6]

            Material Glazed mirror
            ref base floor
            double mirrorCoefficient 0.5

            Surface Sphere
            Vector3d center [-1 0 -2]
            double radius 1
            ref material red

            Surface Sphere
            Vector3d center [1.5 0 -3]
            double radius 1
            ref material mirror

            Surface Triangle
            Vector3d v0 [-30 -1 -30]
            Vector3d v1 [-30 -1 1]
            Vector3d v2 [30 -1 1]
            ref material floor

            Surface Triangle
            Vector3d v0 [-30 -1 -30]
            Vector3d v1 [30 -1 1]
            Vector3d v2 [30 -1 -30]
            ref material floor

            Light PointLight
            Vector3d position [3 8 1]
            Vector3d intensity [60 60 60]

            """;

    static final String GLASS = """
            Material Dielectric glass
            double refractiveIndex %s
            String fresnel exact

            """;

    /** Closed surfaces the glass is made of, each about the same place in front of the camera. */
    static final String[] SHAPES = {
            "Surface Sphere\nVector3d center [0.2 0.3 3]\ndouble radius 1.2\nref material glass\n",
            "Surface Box\nVector3d minPoint [-0.8 -0.7 2.2]\nVector3d maxPoint [1.1 1.2 3.6]\nref material glass\n",
            "Surface Cylinder\nVector3d base [0.2 -0.8 3]\nVector3d axis [0.3 2 -0.4]\ndouble radius 0.9\nref material glass\n",
            "Surface Cone\nVector3d base [0.2 -0.8 3]\nVector3d axis [0 2.2 0.3]\ndouble radius 1.1\nref material glass\n",
            "Surface Torus\nVector3d center [0.2 0.3 3]\nVector3d axis [0.2 0.5 1]\ndouble majorRadius 0.9\n"
                    + "double minorRadius 0.4\nref material glass\n",
    };

    static Image render(String text) throws Exception {
        return new ray.render.Renderer(Parser.parse(text, "invisible.txt", new ArrayList<>())).render();
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 2, 3, 4})
    void indexOneGlassWithExactFresnelIsInvisible(int shape) throws Exception {
        Image without = render(SCENE);
        Image with = render(SCENE + GLASS.formatted("1") + SHAPES[shape]);
        assertEquals(without.rgb.length, with.rgb.length);
        double largest = 0;
        for (int i = 0; i < with.rgb.length; i++) {
            largest = Math.max(largest, Math.abs(with.rgb[i] - without.rgb[i]));
        }
        assertTrue(largest <= 1e-9, "largest channel difference " + largest);

        // the same ball of glass (n 1.5) changes much of the image: the ball covers it, so the
        // comparison above could fail
        Image glass = render(SCENE + GLASS.formatted("1.5") + SHAPES[shape]);
        int changed = 0;
        for (int i = 0; i < glass.rgb.length; i += 3) {
            if (Math.abs(glass.rgb[i] - without.rgb[i]) + Math.abs(glass.rgb[i + 1] - without.rgb[i + 1])
                    + Math.abs(glass.rgb[i + 2] - without.rgb[i + 2]) > 1e-3) {
                changed++;
            }
        }
        assertTrue(changed > glass.rgb.length / 3 / 20, "glass of index 1.5 changed only " + changed + " pixels");
    }
}
