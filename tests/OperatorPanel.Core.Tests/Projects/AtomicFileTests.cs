using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class AtomicFileTests
{
    [Fact]
    public void TryReadAll_FileOverTheLimit_StopsReadingAndSaysSo()
    {
        using var folder = new TempFolder();
        var path = folder.File("big.opproj");
        File.WriteAllBytes(path, new byte[100]);

        AtomicFile.TryReadAll(path, maxBytes: 10, out var bytes, out var error).Should().BeFalse();

        bytes.Should().BeNull();
        error.Should().Be("the file is larger than 10 bytes, the most this kind of file may have");
    }

    [Fact]
    public void TryWrite_OverAnExistingFile_KeepsTheWholePreviousVersionAsBak()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");

        AtomicFile.TryWrite(path, [1, 2, 3], out _).Should().BeTrue();
        File.Exists(path + ".bak").Should().BeFalse();
        AtomicFile.TryWrite(path, [4, 5], out _).Should().BeTrue();
        AtomicFile.TryWrite(path, [6], out var error).Should().BeTrue(error);

        File.ReadAllBytes(path).Should().Equal(6);
        File.ReadAllBytes(path + ".bak").Should().Equal(4, 5);
        Directory.GetFiles(folder.Path).Select(Path.GetFileName).Should().BeEquivalentTo("line.opproj", "line.opproj.bak");
    }

    [Fact]
    public void TryWrite_RemovesTemporaryFilesOfAKilledSave_ButNotFreshOnesOrOtherFiles()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        var stale = folder.File(".line.opproj.0123456789abcdef0123456789abcdef.tmp");
        var fresh = folder.File(".line.opproj.fedcba9876543210fedcba9876543210.tmp");
        var otherProject = folder.File(".other.opproj.0123456789abcdef0123456789abcdef.tmp");
        foreach (var file in new[] { stale, fresh, otherProject })
        {
            File.WriteAllBytes(file, [9]);
        }

        var longAgo = File.GetLastWriteTimeUtc(fresh) - TimeSpan.FromHours(1);
        File.SetLastWriteTimeUtc(stale, longAgo);
        File.SetLastWriteTimeUtc(otherProject, longAgo);

        AtomicFile.TryWrite(path, [1], out var error).Should().BeTrue(error);

        File.Exists(stale).Should().BeFalse();
        File.Exists(fresh).Should().BeTrue("a save running in another process right now keeps its file");
        File.Exists(otherProject).Should().BeTrue();
        File.ReadAllBytes(path).Should().Equal(1);
    }

    [Fact]
    public void TryWrite_FolderMissing_SaysSoInOneSentenceWithoutTheTemporaryName()
    {
        using var folder = new TempFolder();
        var missing = Path.Combine(folder.Path, "plant", "line3");

        AtomicFile.TryWrite(Path.Combine(missing, "line.opproj"), [1], out var error).Should().BeFalse();

        error.Should().Be($"cannot save the file: the folder {missing} does not exist");
        Directory.Exists(missing).Should().BeFalse("a save does not make folders behind the user's back");
    }

    [Fact]
    public void TryWrite_TargetIsAFolder_MessageNamesTheTargetNotTheTemporaryFile()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        Directory.CreateDirectory(path);

        AtomicFile.TryWrite(path, [1], out var error).Should().BeFalse();

        error.Should().StartWith("cannot save the file: ").And.NotContain(".tmp");
        Directory.GetFiles(folder.Path).Should().BeEmpty("the temporary file is gone");
    }

    [Fact]
    public void TryWrite_ReadOnlyTarget_RefusedKeepingTheFileItsBakAndItsMode()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        File.WriteAllBytes(path, [1]);
        File.WriteAllBytes(path + ".bak", [0]);
        File.SetAttributes(path, FileAttributes.ReadOnly);

        // The refusal must come from the mode (0444 here: chmod a-w), not from EACCES: these tests run as root, and the
        // kernel lets root replace or write a 0444 file. So the precondition is the mode bits themselves.
        File.GetAttributes(path).Should().HaveFlag(FileAttributes.ReadOnly);

        AtomicFile.TryWrite(path, [2], out var error).Should().BeFalse();

        error.Should().Be($"cannot save the file: {path} is read-only: nothing written; make it writable to replace it "
            + "(chmod u+w on Linux, clear Read-only in its Properties on Windows), or save elsewhere");
        File.ReadAllBytes(path).Should().Equal(1);
        File.ReadAllBytes(path + ".bak").Should().Equal([0], "the .bak is renewed only when the replacement goes ahead");
        File.GetAttributes(path).Should().HaveFlag(FileAttributes.ReadOnly, "the file keeps its mode");
        Directory.GetFiles(folder.Path).Should().HaveCount(2, "no temporary file is left");
    }

    [UnixFact]
    public void TryWrite_ReadOnlyFolder_RefusedBeforeTheBakIsTouched()
    {
        using var folder = new TempFolder();
        var line = Directory.CreateDirectory(folder.File("line3")).FullName;
        var path = Path.Combine(line, "line.opproj");
        File.WriteAllBytes(path, [1]);
        File.WriteAllBytes(path + ".bak", [0]);
        File.SetAttributes(line, FileAttributes.Directory | FileAttributes.ReadOnly);

        // chmod a-w on the folder. As root the kernel would still let the save create, rename and replace in it, so the
        // test checks the mode bits are set (not an EACCES) and the save must refuse by them.
        File.GetAttributes(line).Should().HaveFlag(FileAttributes.ReadOnly);

        AtomicFile.TryWrite(path, [2], out var error).Should().BeFalse();

        error.Should().Be($"cannot save the file: the folder {line} is read-only: nothing written; make it writable (chmod u+w), or save elsewhere");
        File.ReadAllBytes(path).Should().Equal(1);
        File.ReadAllBytes(path + ".bak").Should().Equal([0], "the .bak is renewed only when the replacement goes ahead");
        Directory.GetFiles(line).Should().HaveCount(2, "no temporary file was made");
    }

    [UnixFact(NeedsRoot = true)]
    public void TryWrite_ImmutableTarget_RefusedBeforeTheBakIsTouched()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        File.WriteAllBytes(path, [1]);
        File.WriteAllBytes(path + ".bak", [0]);
        Chattr("+i", path);
        try
        {
            AtomicFile.TryWrite(path, [2], out var error).Should().BeFalse();

            File.ReadAllBytes(path + ".bak").Should().Equal([0], "before, the .bak was renewed and then the rename failed");
            File.ReadAllBytes(path).Should().Equal(1);
            error.Should().Be("cannot save the file: the system refuses to open it for writing (its permissions, or on Linux an immutable "
                + "or append-only attribute: lsattr shows i or a): nothing written");
            Directory.GetFiles(folder.Path).Should().HaveCount(2, "no temporary file is left");
        }
        finally
        {
            Chattr("-i", path);
        }
    }

    [UnixFact]
    [System.Runtime.Versioning.UnsupportedOSPlatform("windows")]
    public void TryWrite_PrivateFile_NewVersionAndBakKeepItsMode()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        File.WriteAllBytes(path, [1]);
        const UnixFileMode Private = UnixFileMode.UserRead | UnixFileMode.UserWrite;
        File.SetUnixFileMode(path, Private);

        AtomicFile.TryWrite(path, [2], out var error).Should().BeTrue(error);

        File.ReadAllBytes(path).Should().Equal(2);
        File.GetUnixFileMode(path).Should().Be(Private, "a new file would get 0644 from the umask");
        File.GetUnixFileMode(path + ".bak").Should().Be(Private);
    }

    /// <summary>chattr on the file; a file system without the attribute fails the test, it does not pass it.</summary>
    private static void Chattr(string change, string path)
    {
        var start = new System.Diagnostics.ProcessStartInfo("chattr") { RedirectStandardError = true };
        start.ArgumentList.Add(change);
        start.ArgumentList.Add(path);
        using var chattr = System.Diagnostics.Process.Start(start)!;
        var said = chattr.StandardError.ReadToEnd();
        chattr.WaitForExit();
        chattr.ExitCode.Should().Be(0, $"chattr {change} {path}: {said}");
    }
}
