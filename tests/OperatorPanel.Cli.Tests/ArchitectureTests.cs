using System.Reflection;
using System.Text.RegularExpressions;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Cli.Tests;

/// <summary>
/// The layering rules of house-style.md, checked on the built assemblies and the project files. This project sees every
/// assembly but the WPF app, which cannot be built on Linux; the app's project file is checked as text.
/// </summary>
public sealed partial class ArchitectureTests
{
    private static readonly string[] UiAssemblies = ["PresentationFramework", "PresentationCore", "WindowsBase", "System.Xaml"];

    [Fact]
    public void Core_ReferencesNoUiNoMvvmAndNoOtherProject()
    {
        var references = ReferencedNames(typeof(PlcAddress).Assembly);

        references.Should().NotContain(UiAssemblies);
        references.Should().NotContain(r => r.StartsWith("CommunityToolkit", StringComparison.Ordinal) || r.StartsWith("System.Windows", StringComparison.Ordinal));
        references.Should().NotContain(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal) || r == "opanel");
    }

    [Fact]
    public void ViewModels_ReferenceNoWpf()
    {
        var references = ReferencedNames(Assembly.Load("OperatorPanel.ViewModels"));

        references.Should().NotContain(UiAssemblies);
        references.Should().NotContain(r => r.StartsWith("System.Windows", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData("Protocol", "Link")]
    [InlineData("Protocol", "Transport")]
    [InlineData("Transport", "Link")]
    [InlineData("Transport", "Protocol")]
    [InlineData("Link", "Polling")]
    [InlineData("Link", "Line")]
    [InlineData("Polling", "Line")]
    [InlineData("Ppi", "Link")]
    [InlineData("Ppi", "Polling")]
    [InlineData("Ppi", "Line")]
    [InlineData("Ppi", "Protocol")]
    public void CoreFolders_TheWireLayersDoNotImportTheLayersAboveThem(string folder, string above)
    {
        var core = Path.Combine(RepositoryRoot(), "src", "OperatorPanel.Core");
        var importing = Directory.EnumerateFiles(Path.Combine(core, folder), "*.cs", SearchOption.AllDirectories)
            .Where(f => File.ReadAllText(f).Contains($"OperatorPanel.Core.{above}", StringComparison.Ordinal) || File.ReadAllText(f).Contains($" {above}.", StringComparison.Ordinal))
            .Select(Path.GetFileName);

        importing.Should().BeEmpty($"Core/{folder} sits below Core/{above} (one direction: transport, link, polling, line; PPI beside the Freeport protocol, below the bus owner)");
    }

    [Fact]
    public void ViewModels_ReferenceCoreStlGenAndHistorianOnly()
    {
        var assemblies = ReferencedNames(Assembly.Load("OperatorPanel.ViewModels")).Where(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal));
        var projects = ProjectReferencesOf("src/OperatorPanel.ViewModels/OperatorPanel.ViewModels.csproj");

        // StlGen: Generate PLC code builds the StlGen HandlerPackage, the same one `opanel generate` writes.
        // Historian: trends, the alarm journal and the audit read and write the project's history database.
        assemblies.Should().BeSubsetOf(["OperatorPanel.Core", "OperatorPanel.StlGen", "OperatorPanel.Historian"]);
        projects.Should().BeSubsetOf(["OperatorPanel.Core", "OperatorPanel.StlGen", "OperatorPanel.Historian"], "the view models never see the simulator, the CLI or the app");
    }

    [Fact]
    public void Historian_DependsOnCoreOnlyAndNoUi()
    {
        var references = ReferencedNames(Assembly.Load("OperatorPanel.Historian"));

        references.Where(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal)).Should().Equal("OperatorPanel.Core");
        references.Should().NotContain(UiAssemblies);
    }

    [Fact]
    public void Historian_OnlyLineFeedSeesTheLine()
    {
        // The line is being reorganised: the historian meets it in one adapter, so re-pointing it is one file.
        var historian = Path.Combine(RepositoryRoot(), "src", "OperatorPanel.Historian");
        var users = Directory.EnumerateFiles(historian, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains("/obj/", StringComparison.Ordinal) && File.ReadAllText(f).Contains("OperatorPanel.Core.Line", StringComparison.Ordinal))
            .Select(f => Path.GetRelativePath(historian, f).Replace('\\', '/'));

        users.Should().BeEquivalentTo(["Recording/LineFeed.cs", "Historian.cs"]);
    }

    [Fact]
    public void ProjectFiles_OnlyTheViewModelsUseTheMvvmToolkit()
    {
        var users = Directory.EnumerateFiles(Path.Combine(RepositoryRoot(), "src"), "*.csproj", SearchOption.AllDirectories)
            .Where(p => File.ReadAllText(p).Contains("\"CommunityToolkit.Mvvm\"", StringComparison.Ordinal))
            .Select(Path.GetFileNameWithoutExtension);

        users.Should().Equal("OperatorPanel.ViewModels");
    }

    [Theory]
    [InlineData("OperatorPanel.StlGen")]
    [InlineData("OperatorPanel.Simulator")]
    public void StlGenAndSimulator_DependOnCoreAndStlOnly(string assembly)
    {
        var projects = ReferencedNames(Assembly.Load(assembly)).Where(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal));

        projects.Should().BeSubsetOf(["OperatorPanel.Core", "OperatorPanel.Stl"]);
    }

    [Fact]
    public void Demo_DependsOnCoreStlGenAndSimulatorOnly()
    {
        var projects = ReferencedNames(Assembly.Load("OperatorPanel.Demo")).Where(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal));

        projects.Should().BeSubsetOf(["OperatorPanel.Core", "OperatorPanel.StlGen", "OperatorPanel.Simulator"]);
    }

    [Fact]
    public void ProjectFiles_TheAppAndTheCliTakeTheDemoLineFromDemo()
    {
        // One demo line for both front ends (issue 19): the App reaches the simulator only through OperatorPanel.Demo.
        ProjectReferencesOf("src/OperatorPanel.App/OperatorPanel.App.csproj").Should().BeEquivalentTo(["OperatorPanel.ViewModels", "OperatorPanel.Demo"]);
        ProjectReferencesOf("src/OperatorPanel.Cli/OperatorPanel.Cli.csproj").Should().Contain("OperatorPanel.Demo");
        SourceFiles().Select(f => f.Relative).Where(f => Path.GetFileName(f) is "DemoLine.cs" or "DemoLineConnector.cs")
            .Should().BeEquivalentTo(["OperatorPanel.Demo/DemoLine.cs", "OperatorPanel.Demo/DemoLineConnector.cs"]);
    }

    [Fact]
    public void Stl_DependsOnCoreOnly()
    {
        var projects = ReferencedNames(Assembly.Load("OperatorPanel.Stl")).Where(r => r.StartsWith("OperatorPanel.", StringComparison.Ordinal));

        projects.Should().Equal("OperatorPanel.Core");
    }

    [Fact]
    public void Core_HasNoStlFolder()
    {
        // The STL language (reader, parser, instruction table, checks) is its own project, used by StlGen and the
        // Simulator only; the panel's Core never reads .awl text.
        Directory.Exists(Path.Combine(RepositoryRoot(), "src", "OperatorPanel.Core", "Stl")).Should().BeFalse();
    }

    [Fact]
    public void ProjectFiles_NothingButItsTestsReferencesAppOrCli()
    {
        foreach (var project in Directory.EnumerateFiles(RepositoryRoot(), "*.csproj", SearchOption.AllDirectories).Where(p => !p.Contains("/obj/", StringComparison.Ordinal)))
        {
            var name = Path.GetFileNameWithoutExtension(project);
            foreach (Match reference in ProjectReference().Matches(File.ReadAllText(project)))
            {
                var target = Path.GetFileNameWithoutExtension(reference.Groups[1].Value.Replace('\\', '/'));
                target.Should().NotBe("OperatorPanel.App", $"{name} must not reference the WPF app");
                if (name != "OperatorPanel.Cli.Tests")
                {
                    target.Should().NotBe("OperatorPanel.Cli", $"{name} must not reference the CLI");
                }
            }
        }
    }

    [Fact]
    public void Sources_OnlySerialPortTransportUsesSystemIoPorts()
    {
        var offenders = SourceFiles()
            .Where(f => SerialPortApi().IsMatch(File.ReadAllText(f.Path)))
            .Select(f => f.Relative)
            .ToList();

        offenders.Should().Equal(["OperatorPanel.Core/Transport/SerialPortTransport.cs"], "only the serial transport adapter may touch System.IO.Ports");
    }

    [Fact]
    public void Sources_NoPlatformInvoke()
    {
        var offenders = SourceFiles()
            .Where(f => PlatformInvoke().IsMatch(File.ReadAllText(f.Path)))
            .Select(f => f.Relative)
            .ToList();

        offenders.Should().BeEmpty("the serial port goes through System.IO.Ports, so no source calls the OS directly");
    }

    [Fact]
    public void ProjectFiles_OnlyCoreReferencesSystemIoPorts()
    {
        var referencing = Directory.EnumerateFiles(RepositoryRoot(), "*.csproj", SearchOption.AllDirectories)
            .Where(p => File.ReadAllText(p).Contains("\"System.IO.Ports\"", StringComparison.Ordinal))
            .Select(Path.GetFileNameWithoutExtension)
            .ToList();

        referencing.Should().Equal(["OperatorPanel.Core"]);
        ReferencedNames(typeof(PlcAddress).Assembly).Should().Contain("System.IO.Ports");
    }

    private static IEnumerable<(string Path, string Relative)> SourceFiles()
    {
        var src = Path.Combine(RepositoryRoot(), "src");
        return Directory.EnumerateFiles(src, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains("/obj/", StringComparison.Ordinal) && !f.Contains("/bin/", StringComparison.Ordinal))
            .Select(f => (f, Path.GetRelativePath(src, f).Replace('\\', '/')));
    }

    private static List<string> ProjectReferencesOf(string relativePath) =>
        [.. ProjectReference().Matches(File.ReadAllText(Path.Combine(RepositoryRoot(), relativePath)))
            .Select(m => Path.GetFileNameWithoutExtension(m.Groups[1].Value.Replace('\\', '/')))];

    private static List<string> ReferencedNames(Assembly assembly) =>
        assembly.GetReferencedAssemblies().Select(a => a.Name ?? string.Empty).ToList();

    private static string RepositoryRoot()
    {
        var directory = new DirectoryInfo(AppContext.BaseDirectory);
        while (directory is not null && !File.Exists(Path.Combine(directory.FullName, "OperatorPanel.sln")))
        {
            directory = directory.Parent;
        }

        return directory?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above the test output folder");
    }

    [GeneratedRegex("<ProjectReference\\s+Include=\"([^\"]+)\"")]
    private static partial Regex ProjectReference();

    [GeneratedRegex(@"System\.IO\.Ports|\bSerialPort\b")]
    private static partial Regex SerialPortApi();

    [GeneratedRegex(@"DllImport|LibraryImport|\bextern\b")]
    private static partial Regex PlatformInvoke();
}
