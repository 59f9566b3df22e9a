using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// Answers IDENTIFY with a set reply or a set link failure, or with <see cref="Hangs"/> never answers (a port stuck in
/// its driver) until cancelled; records what it was asked and whether it was told to stop.
/// </summary>
internal sealed class FakeConnectionTester : IConnectionTester
{
    public PlcResponse? Reply { get; set; }

    public PlcCommunicationException? Failure { get; set; }

    public List<(SerialSettings Link, Station Station)> Asked { get; } = [];

    public bool Hangs { get; set; }

    public bool ToldToStop { get; private set; }

    public Task<LinkReply> IdentifyAsync(SerialSettings link, Station station, CancellationToken cancellationToken)
    {
        Asked.Add((link, station));
        if (Hangs)
        {
            cancellationToken.Register(() => ToldToStop = true);
            return new TaskCompletionSource<LinkReply>().Task;
        }

        return Task.FromResult<LinkReply>(Failure is not null
            ? new LinkReply.Failed(Failure, Sent: true)
            : new LinkReply.Answered(Reply ?? throw new InvalidOperationException("no reply scripted")));
    }
}
