using System.Runtime.CompilerServices;
using System.Text;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>
/// The export-style programs in tests/StlCorpus, run with the engine of <c>opanel stl run</c> (<see cref="StlRun"/>):
/// the same --set and --print texts a technician types.
/// </summary>
internal static class CorpusProgram
{
    public static CpuProfile Cpu224 => CpuProfiles.For(CpuModel.Cpu224);

    public static string Folder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "..", "StlCorpus"));

    public static string Text(string name) => File.ReadAllText(Path.Combine(Folder(), name), Encoding.Latin1);

    public static StlProgram Load(string name)
    {
        var load = StlProgramLoader.Load(Text(name), Cpu224);
        load.Program.Should().NotBeNull($"{name} loads: {string.Join("; ", load.Diagnostics)}");
        return load.Program!;
    }

    /// <summary>Runs <paramref name="name"/> for <paramref name="seconds"/> of simulated time with the settings (I0.0=1, I0.0=0@2s).</summary>
    public static StlRun Run(string name, double seconds, params string[] settings)
    {
        var run = new StlRun(Load(name));
        var parsed = settings.Select(s => StlSetting.TryParse(s, Cpu224, out var setting, out var error) ? setting : throw new ArgumentException(error)).ToList();
        run.Run(TimeSpan.FromSeconds(seconds), parsed);
        return run;
    }

    public static double Value(this StlRun run, string address) =>
        StlWatch.TryParse(address, Cpu224, out var watch, out var error) ? run.Read(watch) : throw new ArgumentException(error);

    /// <summary>Inputs that pulse: each time gets 1, and 0 50 ms later.</summary>
    public static string[] Pulses(string input, params double[] seconds) =>
        [.. seconds.SelectMany(s => new[] { $"{input}=1@{s}s", $"{input}=0@{s + 0.05}s" })];
}
