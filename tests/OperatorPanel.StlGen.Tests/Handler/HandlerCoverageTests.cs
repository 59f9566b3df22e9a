using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Handler;

public sealed class HandlerCoverageTests
{
    public static TheoryData<CpuModel, CpuRevision, int, int> EveryCpuPortAndBaud()
    {
        var data = new TheoryData<CpuModel, CpuRevision, int, int>();
        foreach (var cpu in CpuProfiles.All)
        {
            for (var port = 0; port < cpu.CommunicationPorts; port++)
            {
                foreach (var rate in cpu.FreeportBaudRates)
                {
                    data.Add(cpu.Model, cpu.Revision, port, rate.Baud);
                }
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(EveryCpuPortAndBaud))]
    public void Generate_EverySupportedSetting_WritesAHandlerInsideTheCpu(CpuModel model, CpuRevision revision, int port, int baud)
    {
        var cpu = CpuProfiles.For(model, revision);

        var result = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = cpu, Port = port, BaudRate = baud, Station = 126 });

        result.Diagnostics.Should().BeEmpty();
        cpu.TryGetArea(MemoryArea.V, out var v).Should().BeTrue();
        result.Stats!.LastVByte.Should().BeLessThanOrEqualTo(v.LastByte).And.BeGreaterThanOrEqualTo(v.LastByte - 1);
        result.AwlText.Should().Contain($", SMB{(port == 0 ? 30 : 130)}\r\n").And.Contain($"RCV    VB{result.Stats.FirstVByte}, {port}");
    }
}
