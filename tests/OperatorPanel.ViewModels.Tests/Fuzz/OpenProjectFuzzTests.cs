using System.Text;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Shell;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Fuzz;

/// <summary>
/// The Open command fed bad project files (seeded byte flips and truncations of a valid file, binary data, another
/// encoding, a folder, a missing file, a 10 MB file): each shows one "Project not opened" message naming the file and a
/// problem, the status line turns to an error, and the current project stays open and connected.
/// </summary>
public sealed class OpenProjectFuzzTests : IAsyncDisposable
{
    /// <summary>Bytes that break JSON structure, a number, or UTF-8 (16#FF never starts a character).</summary>
    private static readonly byte[] FlipTo = [.. "{}[]\",:0x\0"u8, 0xFF];

    private readonly PanelFixture _panel = new();
    private readonly ShellViewModel _shell;
    private readonly string _folder = Directory.CreateTempSubdirectory("opanel-open-fuzz-").FullName;

    public OpenProjectFuzzTests() => _shell = _panel.Shell(new SampleDemo(_panel.Connector));

    [Fact]
    public async Task Open_BadFiles_EachShowsTheProblemAndKeepsTheCurrentProject()
    {
        await _panel.ConnectAsync();
        var project = _panel.Session.Project;
        var failures = new List<string>();
        var cases = 0;
        foreach (var (path, how) in BadFiles())
        {
            cases++;
            _panel.Dialogs.Errors.Clear();
            _panel.Files.FileToOpen = path;

            await _shell.OpenCommand.ExecuteAsync(null).Guarded();

            var shown = _panel.Dialogs.Errors;
            if (shown.Count != 1 || shown[0].Title != "Project not opened" || !shown[0].Message.StartsWith(path, StringComparison.Ordinal)
                || shown[0].Message.Split(Environment.NewLine).Length < 2 || shown[0].Message.Length > 20_000)
            {
                failures.Add($"{how}: {shown.Count} messages: {string.Join(" | ", shown.Select(e => e.Message[..Math.Min(200, e.Message.Length)]))}");
            }

            if (!ReferenceEquals(_panel.Session.Project, project) || !_panel.Session.IsConnected || !_panel.Session.StatusLine.IsError)
            {
                failures.Add($"{how}: the current project was not kept as it was");
            }
        }

        failures.Should().BeEmpty();
        cases.Should().BeGreaterThan(15, "most flips break the file");
    }

    public async ValueTask DisposeAsync()
    {
        await _panel.DisposeAsync();
        Directory.Delete(_folder, recursive: true);
    }

    private IEnumerable<(string Path, string How)> BadFiles()
    {
        var valid = Encoding.UTF8.GetBytes(ProjectFile.Format(PanelFixture.Project()));
        var random = new Random(1200);
        for (var i = 0; i < 12; i++)
        {
            var bytes = (byte[])valid.Clone();
            var at = random.Next(bytes.Length);
            bytes[at] = FlipTo[random.Next(FlipTo.Length)];
            var path = Write($"flip{i}.opproj", bytes);
            if (!ProjectFile.Load(path).Ok)
            {
                // A flip inside a text ('0' in a description) leaves a valid file, which rightly opens.
                yield return (path, $"byte {at} flipped");
            }
        }

        for (var i = 0; i < 6; i++)
        {
            var length = random.Next(valid.Length - 1);
            yield return (Write($"cut{i}.opproj", valid[..length]), $"truncated to {length}");
        }

        var binary = new byte[4096];
        random.NextBytes(binary);
        yield return (Write("binary.opproj", binary), "binary");
        yield return (Write("utf16.opproj", [.. Encoding.Unicode.GetPreamble(), .. Encoding.Unicode.GetBytes(ProjectFile.Format(PanelFixture.Project()))]), "UTF-16");
        yield return (Write("huge.opproj", Encoding.UTF8.GetBytes(new string(' ', 10 << 20) + "[")), "10 MB of spaces");
        yield return (Write("empty.opproj", []), "empty");
        yield return (Path.Combine(_folder, "missing.opproj"), "missing");
        yield return (Directory.CreateDirectory(Path.Combine(_folder, "folder.opproj")).FullName, "a folder");
    }

    private string Write(string name, byte[] bytes)
    {
        var path = Path.Combine(_folder, name);
        File.WriteAllBytes(path, bytes);
        return path;
    }
}
