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
}
