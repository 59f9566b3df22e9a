using System.Xml.Linq;
using OperatorPanel.ViewModels.Help;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Help;

public sealed class AboutViewModelTests : IDisposable
{
    private readonly TempFolder _folder = new();

    [Fact]
    public void VersionText_IsTheProductVersionTheMsiCarries()
    {
        var props = XDocument.Load(Path.Combine(RepositoryRoot(), "Directory.Build.props"));
        var version = props.Descendants("Version").First().Value;

        new AboutViewModel(_folder.File("README.txt"), null).VersionText.Should().Be($"Version {version}");
    }

    [Fact]
    public void OpenReadme_FilePresent_OpensItWithTheLauncher()
    {
        var readme = _folder.File("README.txt");
        File.WriteAllText(readme, "# Operator Panel");
        var launcher = new RecordingLauncher();
        var about = new AboutViewModel(readme, launcher);

        about.OpenReadmeCommand.Execute(null);

        launcher.Opened.Should().Equal(readme);
        about.Message.Should().BeNull();
    }

    [Fact]
    public void OpenReadme_FileMissing_SaysSoAndOpensNothing()
    {
        var readme = _folder.File("README.txt");
        var launcher = new RecordingLauncher();
        var about = new AboutViewModel(readme, launcher);

        about.OpenReadmeCommand.Execute(null);

        launcher.Opened.Should().BeEmpty();
        about.Message.Should().Be($"{readme} is missing; reinstall the panel to get it back.");
    }

    [Fact]
    public async Task ShowAbout_FromTheShell_PointsAtTheReadmeBesideTheProgram()
    {
        await using var panel = new PanelFixture();
        var shell = panel.Shell();

        shell.ShowAboutCommand.Execute(null);

        shell.About!.ReadmePath.Should().Be(Path.Combine(AppContext.BaseDirectory, "README.txt"));
        shell.CloseAbout();
        shell.About.Should().BeNull();
    }

    public void Dispose() => _folder.Dispose();

    private static string RepositoryRoot()
    {
        var folder = new DirectoryInfo(AppContext.BaseDirectory);
        while (folder is not null && !File.Exists(Path.Combine(folder.FullName, "OperatorPanel.sln")))
        {
            folder = folder.Parent;
        }

        return folder!.FullName;
    }

    private sealed class RecordingLauncher : IDocumentLauncher
    {
        public List<string> Opened { get; } = [];

        public bool TryOpen(string path, out string? error)
        {
            Opened.Add(path);
            error = null;
            return true;
        }
    }
}
