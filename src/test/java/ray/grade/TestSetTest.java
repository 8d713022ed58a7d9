package ray.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The rubric format: what it reads, and a mistake reported as rubric.txt:LINE. */
class TestSetTest {

    @TempDir
    Path dir;

    Path rubric(String body) throws IOException {
        for (String d : List.of("fw", "checks", "scenes", "refs")) {
            Files.createDirectories(dir.resolve(d));
        }
        Files.writeString(dir.resolve("scenes/a.txt"), "Width 1\n");
        Files.writeString(dir.resolve("refs/a.png"), "");
        Files.writeString(dir.resolve("refs/a-2.png"), "");   // a second independent render, for the stochastic scene
        Files.writeString(dir.resolve("rubric.txt"), "framework fw\nchecks checks\nscenes scenes\nreferences refs\n" + body);
        return dir;
    }

    @Test
    void readsGroupsItemsPointsAndLimits() throws IOException {
        TestSet t = TestSet.load(rubric("""
                render R.render
                method A.m   # the first method
                limit heap-mb 200
                group One
                check 2.5 C.x  A.m: does x
                group Two
                scene 3 a.txt stochastic renders=6 uses=A.m,B.n  The scene a
                """));
        assertEquals(List.of("One", "Two"), t.groups());
        assertEquals(5.5, t.maxScore());
        assertEquals(2.5, t.maxScore("One"));
        assertEquals(List.of("A.m"), t.methods());
        assertEquals(200, t.limits().heapMb());
        TestSet.Item s = t.items().get(1);
        assertEquals(TestSet.Kind.SCENE, s.kind());
        assertTrue(s.stochastic());
        assertEquals(List.of("A.m", "B.n"), s.uses());
        assertEquals(6, s.renders());
        assertEquals(List.of(dir.resolve("refs/a.png"), dir.resolve("refs/a-2.png")), TestSet.referenceRenders(t.references(), "a.txt"));
        assertEquals("The scene a", s.title());
        assertEquals("A.m: does x", t.items().get(0).title());
    }

    @Test
    void mistakesNameTheLine() throws IOException {
        assertMistake("group G\ncheck two C.x T\n", "rubric.txt:6: two is not a number");
        assertMistake("check 1 C.x T\n", "rubric.txt:5: check before the first group line");
        assertMistake("group G\ncheck 1 notAMethod T\n", "rubric.txt:6: check notAMethod is not CLASS.METHOD");
        assertMistake("limit speed 3\n", "rubric.txt:5: unknown limit speed");
        assertMistake("grop G\n", "rubric.txt:5: unknown line \"grop\"");
        assertMistake("render R.r\ngroup G\nscene 1 missing.txt T\n", "scene missing.txt is not in");
        assertMistake("group G\nscene 1 a.txt T\n", "scenes need a \"render CLASS.METHOD\" line");
        assertMistake("group G\ngroup G\n", "rubric.txt:6: group \"G\" appears twice");
        assertMistake("", "no check or scene lines");
        assertMistake("render R.r\ngroup G\nscene 1 a.txt renders=3 T\n", "rubric.txt:7: renders= goes with stochastic");
        assertMistake("render R.r\ngroup G\nscene 1 a.txt stochastic renders=1 T\n", "renders= takes a whole number from 2 to 64");
    }

    void assertMistake(String body, String expected) throws IOException {
        Path d = rubric(body);
        IOException e = assertThrows(IOException.class, () -> TestSet.load(d));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void aStochasticSceneNeedsSeveralReferenceRenders() throws IOException {
        Path d = rubric("render R.r\ngroup G\nscene 1 a.txt stochastic T\n");
        Files.delete(d.resolve("refs/a-2.png"));
        IOException e = assertThrows(IOException.class, () -> TestSet.load(d));
        assertTrue(e.getMessage().contains("needs independent reference renders a.png, a-2.png"), e.getMessage());
    }

    @Test
    void aFolderWithoutRubricIsNotATestSet() {
        IOException e = assertThrows(IOException.class, () -> TestSet.load(dir));
        assertTrue(e.getMessage().contains("no rubric.txt"), e.getMessage());
    }
}
