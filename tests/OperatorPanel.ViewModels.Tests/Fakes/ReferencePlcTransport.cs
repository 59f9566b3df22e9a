using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>A transport whose far end is a simulated protocol v3 PLC answering each frame at once (no end time-out, no clock).</summary>
internal sealed class ReferencePlcTransport(ReferenceHandler plc) : ITransport
{
    private readonly Queue<byte> _replies = new();

    public string Name => "simulated";

    public bool IsOpen { get; private set; }

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        IsOpen = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        foreach (var b in plc.HandleMessage(data.Span) ?? [])
        {
            _replies.Enqueue(b);
        }

        return Task.CompletedTask;
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var count = 0;
        while (count < buffer.Length && _replies.TryDequeue(out var b))
        {
            buffer.Span[count++] = b;
        }

        return Task.FromResult(count);
    }

    public void DiscardInput() => _replies.Clear();

    public ValueTask DisposeAsync()
    {
        IsOpen = false;
        return ValueTask.CompletedTask;
    }
}
