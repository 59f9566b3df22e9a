using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Golden;

public sealed class HandlerGoldenTests
{
    internal static HandlerOptions Cpu224Port0Station2 => new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 };

    internal static HandlerOptions Cpu226Port1Station17 => new()
    {
        Protocol = 2,
        Cpu = CpuProfiles.For(CpuModel.Cpu226),
        Port = 1,
        BaudRate = 19200,
        Parity = Parity.Even,
        Station = 17,
        BufferStart = 1000,
        CharTimeoutMs = 100,
    };

    internal static HandlerOptions Cpu221EarlyStation1 => new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu221, CpuRevision.Early), Station = 1 };

    public static TheoryData<string> Cases => ["Cpu224_Port0_9600_2", "Cpu226_Port1_19200_17", "Cpu221Early_Port0_9600_1"];

    internal static HandlerOptions OptionsFor(string name) => name switch
    {
        "Cpu224_Port0_9600_2" => Cpu224Port0Station2,
        "Cpu226_Port1_19200_17" => Cpu226Port1Station17,
        _ => Cpu221EarlyStation1,
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Generate_GoldenConfiguration_MatchesAwlByteForByte(string name)
    {
        var result = HandlerGenerator.Generate(OptionsFor(name));

        result.Diagnostics.Should().BeEmpty();
        GoldenFile.Match(name + ".awl", result.AwlText);
    }

    [Fact]
    public void Generate_Cpu224Station2_MatchesSymbolTableAndNotes()
    {
        var result = HandlerGenerator.Generate(Cpu224Port0Station2);

        GoldenFile.Match("Cpu224_Port0_9600_2-symbols.txt", result.SymbolTableText);
        GoldenFile.Match("Cpu224_Port0_9600_2-README.txt", result.TechnicianText);
    }
}
