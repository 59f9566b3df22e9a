using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class ProjectFileSaveTests
{
    private static readonly PanelProject Sample = ProjectFile.Parse(SampleProject.Text).Project!;

    [Fact]
    public void TrySave_NewFile_WritesTheFormattedProjectAndNoBackup()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");

        ProjectFile.TrySave(Sample, path, out var error).Should().BeTrue(error);

        File.ReadAllText(path).Should().Be(SampleProject.Text);
        File.Exists(path + ".bak").Should().BeFalse();
        Directory.GetFiles(folder.Path).Should().ContainSingle("no temporary file is left behind");
    }

    [Fact]
    public void TrySave_ExistingFile_KeepsThePreviousContentAsBak()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        File.WriteAllText(path, "previous content");
        var renamed = Sample with { Name = "Bottling line 2" };

        ProjectFile.TrySave(renamed, path, out var error).Should().BeTrue(error);

        File.ReadAllText(path + ".bak").Should().Be("previous content");
        ProjectFile.Load(path).Project!.Name.Should().Be("Bottling line 2");
        Directory.GetFiles(folder.Path).Should().HaveCount(2);
    }

    [Fact]
    public void TrySave_Twice_BakHoldsTheSecondToLastVersion()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");

        ProjectFile.TrySave(Sample with { Name = "one" }, path, out _).Should().BeTrue();
        ProjectFile.TrySave(Sample with { Name = "two" }, path, out _).Should().BeTrue();
        ProjectFile.TrySave(Sample with { Name = "three" }, path, out _).Should().BeTrue();

        ProjectFile.Load(path + ".bak").Project!.Name.Should().Be("two");
        ProjectFile.Load(path).Project!.Name.Should().Be("three");
    }

    [Fact]
    public void TrySave_MissingFolder_FailsWithAMessageAndWritesNothing()
    {
        using var folder = new TempFolder();
        var path = Path.Combine(folder.Path, "no-such-folder", "line.opproj");

        ProjectFile.TrySave(Sample, path, out var error).Should().BeFalse();

        error.Should().StartWith("cannot save the file: ");
        Directory.GetFileSystemEntries(folder.Path).Should().BeEmpty();
    }

    [Fact]
    public void TrySave_TargetIsAFolder_FailsAndLeavesNoTemporaryFile()
    {
        using var folder = new TempFolder();
        var path = folder.File("line.opproj");
        Directory.CreateDirectory(path);

        ProjectFile.TrySave(Sample, path, out var error).Should().BeFalse();

        error.Should().StartWith("cannot save the file: ");
        Directory.GetFiles(folder.Path).Should().BeEmpty();
    }
}
