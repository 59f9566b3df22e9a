namespace OperatorPanel.Historian.Tests;

/// <summary>One database per project file, and a separate one for its demo line.</summary>
public sealed class HistoryFolderTests
{
    private readonly HistoryFolder _folder = new(Path.Combine(Path.GetTempPath(), "history"));

    [Fact]
    public void DatabaseFor_SameFile_IsTheSameDatabase()
    {
        _folder.DatabaseFor("/lines/a/line.opproj", demo: false).Should().Be(_folder.DatabaseFor("/lines/a/../a/line.opproj", demo: false));
    }

    [Fact]
    public void DatabaseFor_SameNameInAnotherFolder_IsAnotherDatabase()
    {
        _folder.DatabaseFor("/lines/a/line.opproj", demo: false).Should().NotBe(_folder.DatabaseFor("/lines/b/line.opproj", demo: false));
    }

    [Fact]
    public void DatabaseFor_Demo_IsAnotherDatabaseNamedSo()
    {
        var demo = _folder.DatabaseFor("/lines/a/line.opproj", demo: true);

        demo.Should().EndWith("-demo.history.db");
        demo.Should().NotBe(_folder.DatabaseFor("/lines/a/line.opproj", demo: false));
    }

    [Fact]
    public void DatabaseFor_NameWithSpaces_IsAFileNameInTheFolder()
    {
        var path = _folder.DatabaseFor("/lines/Bottling line 1.opproj", demo: false);

        Path.GetDirectoryName(path).Should().Be(_folder.Path);
        Path.GetFileName(path).Should().MatchRegex("^bottling-line-1-[0-9a-f]{8}\\.history\\.db$");
    }
}
