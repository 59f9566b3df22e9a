using System.Runtime.CompilerServices;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Golden;

/// <summary>
/// The Simulator's tests load generated handlers as text (the Simulator never references StlGen), so their copies in
/// tests/OperatorPanel.Simulator.Tests/Hosting must stay what the generator writes today: they are golden files of
/// this generator (OPANEL_BLESS=1 rewrites them).
/// </summary>
public sealed class SimulatorHandlerCopiesTests
{
    [Theory]
    [InlineData(2)]
    [InlineData(3)]
    public void Generate_Cpu224Station_MatchesTheSimulatorTestsEmbeddedCopy(int station)
    {
        var result = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2 with { Station = station });

        result.Diagnostics.Should().BeEmpty();
        GoldenFile.MatchAt(Path.Combine(HostingFolder(), $"Handler224Station{station}.awl"), result.AwlText);
    }

    private static string HostingFolder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "OperatorPanel.Simulator.Tests", "Hosting"));
}
