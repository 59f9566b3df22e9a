using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Handlers;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>The v3 handler generated for <c>options</c> and measured as `generate --stats` measures it (station 2, port 0, 8N1).</summary>
internal static class V3Measured
{
    public static ImmutableArray<MeasuredRequest> Requests(HandlerOptions options)
    {
        var generated = HandlerGenerator.Generate(options);
        generated.Ok.Should().BeTrue(string.Join("; ", generated.Diagnostics));
        V3Measurement.TryMeasure(
            generated.AwlText, options.Cpu, 0, new Station(options.Station), new LineSettings(options.BaudRate, Parity.None, 8),
            options.Compact ? HandlerShape.Compact : HandlerShape.Full, out var requests, out var error).Should().BeTrue(error);
        return requests;
    }
}
