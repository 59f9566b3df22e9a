using System.Runtime.CompilerServices;
using System.Text;

namespace OperatorPanel.StlGen.Tests.Golden;

/// <summary>
/// Byte-for-byte golden files beside this source file. A mismatch writes NAME.received.EXT next to the golden file
/// (Verify's naming; git-ignored) and fails. To re-bless after an intended change, run the tests with
/// OPANEL_BLESS=1 (the golden files are then rewritten) and review the diff before committing.
/// </summary>
internal static class GoldenFile
{
    public static void Match(string name, string actual, [CallerFilePath] string caller = "") =>
        MatchAt(Path.Combine(Path.GetDirectoryName(caller)!, name), actual);

    /// <summary>The same for a golden file elsewhere in the repository, e.g. another test project's embedded copy.</summary>
    public static void MatchAt(string path, string actual)
    {
        var folder = Path.GetDirectoryName(path)!;
        var name = Path.GetFileName(path);
        var bytes = Encoding.ASCII.GetBytes(actual);
        if (Environment.GetEnvironmentVariable("OPANEL_BLESS") == "1")
        {
            File.WriteAllBytes(path, bytes);
            return;
        }

        var received = Path.Combine(folder, Path.GetFileNameWithoutExtension(name) + ".received" + Path.GetExtension(name));
        var expected = File.Exists(path) ? File.ReadAllBytes(path) : [];
        if (expected.AsSpan().SequenceEqual(bytes))
        {
            File.Delete(received);
            return;
        }

        File.WriteAllBytes(received, bytes);
        var at = FirstDifference(expected, bytes);
        Assert.Fail($"{name} differs from the golden file at byte {at} ({expected.Length} expected, {bytes.Length} received); see {received}. Re-bless with OPANEL_BLESS=1 if intended.");
    }

    private static int FirstDifference(byte[] a, byte[] b)
    {
        var n = Math.Min(a.Length, b.Length);
        for (var i = 0; i < n; i++)
        {
            if (a[i] != b[i])
            {
                return i;
            }
        }

        return n;
    }
}
