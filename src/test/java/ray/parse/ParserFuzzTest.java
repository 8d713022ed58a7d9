package ray.parse;

import com.code_intelligence.jazzer.junit.DictionaryEntries;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Timeout;

/**
 * Jazzer fuzz test of the scene parser: whatever the bytes, the parser may only succeed or throw a
 * one-line {@link SceneFormatException} naming the file; no other exception, no hang (the timeout is
 * per input), no memory blow-up (the fuzz JVM's heap is small).
 *
 * <p>{@code gradle test} runs it in regression mode: once on each file of
 * {@code src/test/resources/ray/parse/ParserFuzzTestInputs/parseOnlyThrowsSceneFormatException/} (the
 * seed corpus; the build adds every {@code scenes/*.txt} up to 64 KB). {@code gradle fuzz -PfuzzSeconds=60} fuzzes; a
 * crashing input lands in that directory as {@code crash-<sha1>}: rename it to say what it tests,
 * fix the parser, and commit it as a regression input.
 */
class ParserFuzzTest {

    /**
     * The first parse loads (and the fuzzer instruments) the parser's classes and, at the first class it
     * cannot find, the built-in classes its message lists: seconds on a loaded machine, once per JVM. Done
     * here, so the per-input timeout times the inputs, as it means to.
     */
    @BeforeAll
    static void loadTheParserOnce() {
        ParserInvariant.check("Width 1\nHeight 1\n\nCamera Camera\n\nSurface Sphear\n\n".getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }

    @Timeout(value = 3, unit = TimeUnit.SECONDS)
    @DictionaryEntries({"Camera", "Surface", "Material", "Light", "Sphere", "Triangle", "Diffuse", "BlinnPhong",
        "GlazedMaterial", "Glazed", "PointLight", "Width", "Height", "AASamples", "MaxDepth", "BGColor", "AmbientLight",
        "int", "double", "String", "ref", "Vector3d", "eye", "target", "up", "yFOV", "aspect", "center", "radius",
        "material", "v0", "v1", "v2", "ambientColor", "diffuseColor", "specularColor", "exponent", "base",
        "mirrorCoefficient", "position", "intensity", "[", "]", "#", "NaN", "Infinity", "1e999", "-0", "2147483648",
        "FieldZooSurface", "EvilNotASurface", "InitFlagSurface", "label", "big", "small", "boxed"})
    @FuzzTest(maxDuration = "60s")
    void parseOnlyThrowsSceneFormatException(byte[] data) {
        ParserInvariant.check(data);
    }
}
